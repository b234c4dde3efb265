"""Findings: design problems a stage found that leave the design computable but poor."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Finding:
    """A design problem found by a check: ``code`` names it, the messages say what to change."""

    code: str
    zh: str
    en: str

    def text(self, lang: str) -> str:
        return self.zh if lang == "zh" else self.en

"""Findings: design problems a stage found that leave the design computable but poor."""
from __future__ import annotations

from dataclasses import dataclass

from ..core.fields import q


@dataclass(frozen=True)
class Finding:
    """A design problem found by a check: ``code`` names it, the messages say what to change."""

    code: str = q("", "the problem's name")
    zh: str = q("", "what it is and what to change (中文)")
    en: str = q("", "what it is and what to change (English)")
    field: str = q("", "the brief field it is about, when it is about one", default="")

    def text(self, lang: str) -> str:
        return self.zh if lang == "zh" else self.en

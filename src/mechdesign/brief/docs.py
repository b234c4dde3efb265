"""Markdown reference of a brief model: every field with its unit, default and range.

``python -m mechdesign.brief.docs > docs/brief.md`` regenerates the committed file;
a test checks that it is up to date.
"""
from __future__ import annotations

from pydantic import BaseModel

from .loader import BRIEF_MODELS

_BOUNDS = {"gt": ">", "ge": "≥", "lt": "<", "le": "≤"}


def _allowed(info) -> str:
    parts = []
    for meta in info.metadata:
        for key, sym in _BOUNDS.items():
            value = getattr(meta, key, None)
            if value is not None:
                parts.append(f"{sym} {value:g}")
        if getattr(meta, "min_length", None):
            parts.append("non-empty")
    args = getattr(info.annotation, "__args__", None)
    if args and all(isinstance(a, str) for a in args):
        parts.append(" \\| ".join(args))
    return ", ".join(parts)


def _rows(model: type[BaseModel], prefix: str):
    for name, info in model.model_fields.items():
        key = info.alias or name
        path = f"{prefix}{key}"
        ann = info.annotation
        if isinstance(ann, type) and issubclass(ann, BaseModel):
            yield f"| **{path}** | section | | {ann.__doc__.strip().splitlines()[0]} |"
            yield from _rows(ann, path + ".")
        else:
            default = "required" if info.is_required() else f"`{info.default}`"
            desc = (info.description or "").replace("|", "\\|")
            allowed = _allowed(info)
            yield f"| `{path}` | {default} | {allowed} | {desc} |"


def brief_markdown() -> str:
    out = ["# Design brief reference", "",
           "Generated from the brief models (`python -m mechdesign.brief.docs`). Units are in",
           "the field names and descriptions; every value is converted to SI once, on loading.",
           "Unknown keys are errors.", ""]
    for machine, model in sorted(BRIEF_MODELS.items()):
        out += [f"## machine: {machine}", "", model.__doc__.strip(), "",
                "| field | default | allowed | meaning [unit] |", "|---|---|---|---|"]
        out += list(_rows(model, ""))
        out.append("")
    return "\n".join(out)


if __name__ == "__main__":
    print(brief_markdown())

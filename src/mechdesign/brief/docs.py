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
    literals = []
    if float in (getattr(info.annotation, "__args__", None) or ()):
        literals.append("a number")
    for arg in getattr(info.annotation, "__args__", None) or ():
        if isinstance(arg, str):
            literals.append(arg)
        elif getattr(arg, "__args__", None) and all(isinstance(a, str) for a in arg.__args__):
            literals.extend(arg.__args__)      # Optional[Literal[...]] / Union[float, Literal]
    if literals:
        parts.append(" \\| ".join(literals))
    return ", ".join(parts)


def _section(ann):
    """(model, is_list, optional) if ``ann`` is a brief section, a list of them or an
    optional section; else None."""
    if isinstance(ann, type) and issubclass(ann, BaseModel):
        return ann, False, False
    args = [a for a in getattr(ann, "__args__", ()) if a is not type(None)]
    origin = getattr(ann, "__origin__", None)
    if origin is list and args and isinstance(args[0], type) and issubclass(args[0], BaseModel):
        return args[0], True, False
    if len(args) == 1 and isinstance(args[0], type) and issubclass(args[0], BaseModel):
        return args[0], False, True
    return None


def _rows(model: type[BaseModel], prefix: str):
    for name, info in model.model_fields.items():
        key = info.alias or name
        path = f"{prefix}{key}"
        ann = info.annotation
        section = _section(ann)
        if section is not None:
            sub, many, optional = section
            what = "list of" if many else ("optional section" if optional else "section")
            yield f"| **{path}** | {what} | | {sub.__doc__.strip().splitlines()[0]} |"
            yield from _rows(sub, path + ("[].") if many else path + ".")
        else:
            default = ("required" if info.is_required() else
                       f"`{info.default_factory()}`" if info.default_factory is not None
                       else f"`{info.default}`")
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

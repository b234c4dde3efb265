"""Number formatting shared by every report context (the templates get strings only)."""
from __future__ import annotations


def f(x: float, digits: int = 2) -> str:
    """Fixed-point number with ``digits`` decimals; a rounded zero never shows as '-0.00'."""
    text = f"{x:.{digits}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


def e(x: float) -> str:
    """Small residuals in scientific notation for the verification tables."""
    return f"{x:.1e}"

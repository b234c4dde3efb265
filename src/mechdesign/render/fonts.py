"""Locate the Chinese (CJK) fonts used by the PDF report and the figures.

The preferred source is the ``pylopdf_fonts_zh_cn`` package, which ships
Noto Serif SC / Noto Sans SC (Regular weight only).  Without it, common system
font directories are searched for Noto CJK, Source Han, SimSun/SimHei or
Microsoft YaHei files.
"""

from __future__ import annotations

import os
from functools import lru_cache
from pathlib import Path

# (file-name prefix in lower case, typst/matplotlib family name, role)
_FALLBACK_FONTS = [
    ("notoserifsc", "Noto Serif SC", "serif"),
    ("notosanssc", "Noto Sans SC", "sans"),
    ("notoserifcjk", "Noto Serif CJK SC", "serif"),
    ("notosanscjk", "Noto Sans CJK SC", "sans"),
    ("sourcehanserif", "Source Han Serif SC", "serif"),
    ("sourcehansans", "Source Han Sans SC", "sans"),
    ("simsun", "SimSun", "serif"),
    ("simhei", "SimHei", "sans"),
    ("msyh", "Microsoft YaHei", "sans"),
]
_FONT_SUFFIXES = {".otf", ".ttf", ".ttc", ".otc"}


def _system_font_dirs() -> list[Path]:
    """Return the usual system/user font directories that exist on this machine."""
    home = Path.home()
    candidates = [
        Path("/usr/share/fonts"),
        Path("/usr/local/share/fonts"),
        home / ".fonts",
        home / ".local/share/fonts",
        Path("/Library/Fonts"),
        Path("/System/Library/Fonts"),
        home / "Library/Fonts",
        Path(os.environ.get("WINDIR", r"C:\Windows")) / "Fonts",
    ]
    return [d for d in candidates if d.is_dir()]


@lru_cache(maxsize=1)
def _scan_system_fonts() -> tuple[tuple[Path, str, str], ...]:
    """Find CJK font files in system directories.

    Returns tuples ``(file, family, role)`` ordered by preference
    (the order of ``_FALLBACK_FONTS``).
    """
    found: list[tuple[int, Path, str, str]] = []
    for root in _system_font_dirs():
        for path in root.rglob("*"):
            if path.suffix.lower() not in _FONT_SUFFIXES:
                continue
            name = path.name.lower().replace("-", "").replace("_", "")
            for rank, (prefix, family, role) in enumerate(_FALLBACK_FONTS):
                if name.startswith(prefix):
                    found.append((rank, path, family, role))
                    break
    found.sort(key=lambda item: (item[0], str(item[1])))
    return tuple((path, family, role) for _, path, family, role in found)


def _package_fonts() -> dict[str, Path] | None:
    """Return ``{"serif": file, "sans": file}`` from pylopdf_fonts_zh_cn, or None."""
    try:
        import pylopdf_fonts_zh_cn as pkg
    except ImportError:
        return None
    serif, sans = Path(pkg.serif_path()), Path(pkg.sans_path())
    if serif.is_file() and sans.is_file():
        return {"serif": serif, "sans": sans}
    return None


def register_ezdxf_fonts() -> None:
    """Let ezdxf measure texts (the DXF extents) in the shipped CJK fonts: its font manager
    knows only the system's fonts, and a bare machine has none, so every text would be
    measured in a fallback font. Adds the package's font files once, when missing."""
    pkg = _package_fonts()
    if not pkg:
        return
    from ezdxf.fonts import fonts

    if not all(fonts.font_manager.has_font(f.name) for f in pkg.values()):
        fonts.font_manager.scan_folder(pkg["sans"].parent)


def font_dirs() -> list[Path]:
    """Directories holding the CJK fonts, to pass to typst's ``font_paths``.

    Returns the pylopdf_fonts_zh_cn package directory when available, else the
    (deduplicated) directories of CJK font files found on the system; may be empty.
    """
    pkg = _package_fonts()
    if pkg:
        return [pkg["serif"].parent]
    dirs: list[Path] = []
    for path, _, _ in _scan_system_fonts():
        if path.parent not in dirs:
            dirs.append(path.parent)
    return dirs


def _font_files() -> dict[str, Path]:
    """Return the preferred CJK font file per role ("serif"/"sans"); may be partial."""
    pkg = _package_fonts()
    if pkg:
        return pkg
    files: dict[str, Path] = {}
    for path, _, role in _scan_system_fonts():
        files.setdefault(role, path)
    return files


def cjk_families() -> dict[str, str]:
    """Family names of the CJK fonts: ``{"serif": ..., "sans": ...}``.

    ``Noto Serif SC`` / ``Noto Sans SC`` when the font package is installed,
    otherwise the best system fallback (a missing role borrows the other one;
    with nothing found the Noto names are returned and typst will fall back).
    """
    if _package_fonts():
        return {"serif": "Noto Serif SC", "sans": "Noto Sans SC"}
    families: dict[str, str] = {}
    for _, family, role in _scan_system_fonts():
        families.setdefault(role, family)
    serif = families.get("serif") or families.get("sans") or "Noto Serif SC"
    sans = families.get("sans") or families.get("serif") or "Noto Sans SC"
    return {"serif": serif, "sans": sans}


_registered: set[Path] = set()


def configure_matplotlib() -> None:
    """Make matplotlib render Chinese text (idempotent, safe to call repeatedly).

    Registers the CJK sans font file with matplotlib's font manager (once) and
    sets rcParams: sans-serif family with the CJK font first and DejaVu Sans as
    fallback, ASCII minus signs, and DejaVu Sans mathtext.
    """
    import matplotlib
    from matplotlib import font_manager

    files = _font_files()
    font_file = files.get("sans") or files.get("serif")
    family = "DejaVu Sans"
    if font_file is not None:
        if font_file not in _registered:
            font_manager.fontManager.addfont(str(font_file))
            _registered.add(font_file)
        family = font_manager.FontProperties(fname=str(font_file)).get_name()
    _register_display_font(font_manager)

    # DejaVu Sans also as the fallback of single glyphs the CJK font lacks (the dot operator
    # of "N⋅m", render/figures.py narrow_unit_dots): matplotlib falls back along this list
    matplotlib.rcParams["font.family"] = ["sans-serif", "DejaVu Sans"]
    matplotlib.rcParams["font.sans-serif"] = [family, "DejaVu Sans"]
    # tick labels with the true minus sign (U+2212), like the text; the shipped font has it
    matplotlib.rcParams["axes.unicode_minus"] = True
    matplotlib.rcParams["mathtext.fontset"] = "dejavusans"
    # mathtext's DejaVu set looks up its STIX and Computer Modern fallbacks by name when it
    # is first built; where matplotlib's font list lacks them it falls back to DejaVu Sans
    # (every glyph the figures use is there) and logged 21 "findfont: … not found" lines
    # on the user's terminal in the middle of the progress display
    import logging

    logging.getLogger("matplotlib.font_manager").setLevel(logging.ERROR)


def _register_display_font(font_manager) -> None:
    """Register matplotlib's own DejaVu Sans Display when its font list lacks it (a font
    cache written by another installation lists the system's DejaVu files only).

    The "dejavusans" mathtext set takes every glyph the display font has from that font,
    upright; without it the lookup falls back to DejaVu Sans, which has every glyph, and
    the math italic letters (point names, symbols) came out upright — the same figure
    italic on one machine and upright on another. The display font holds only the large
    operators, so the letters come from DejaVu Sans Oblique as matplotlib intends."""
    import matplotlib

    if any(f.name == "DejaVu Sans Display" for f in font_manager.fontManager.ttflist):
        return
    path = Path(matplotlib.get_data_path()) / "fonts" / "ttf" / "DejaVuSansDisplay.ttf"
    if path.is_file() and path not in _registered:
        font_manager.fontManager.addfont(str(path))
        _registered.add(path)          # (addfont clears findfont's cache)

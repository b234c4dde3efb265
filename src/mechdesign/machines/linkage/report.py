"""Report of the `linkage` machine: the shared linkage section (:mod:`mechdesign.render.linkage_report`) for the brief's linkage."""
from __future__ import annotations

from pathlib import Path
from ...i18n import tr
from ...render.fmt import md_meta, md_text
from ...render.linkage_report import linkage_context, make_linkage_figures, verification_rows


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    return make_linkage_figures(r["params"], r["linkage"], r["linkage_forces"],
                                r["linkage_flywheel"], fig_dir, lang)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    _ = tr(lang)
    k, v = r["linkage"], r["linkage_verification"]
    lk = linkage_context(r["params"], k, r["linkage_forces"], r["linkage_flywheel"], v,
                         figures, lang, title=_.pgettext("linkage machine", "Linkage analysis"))
    warnings = [md_text(w.text(lang)) for w in v.warnings]
    return {"meta": md_meta(brief.report, lang), "linkage": lk, "verify_rows": verification_rows(v, lang, k),
            "findings": warnings}


def animate(r: dict, path: Path, lang: str) -> Path:
    """GIF of the linkage over one revolution."""
    from ...render.animation import linkage_gif

    return linkage_gif(r["params"], r["linkage"], path, lang)

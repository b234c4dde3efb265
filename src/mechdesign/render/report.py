"""Write a report: figures, Markdown from the Jinja2 template, results.json, PDF.

Everything is written into a staging folder inside the output folder; only when all of
it succeeded are the files moved into place (:mod:`mechdesign.publish`: the run owns only
the files its manifest lists), so a failed run leaves no half-written report (and an
earlier report stays as it was).
"""
from __future__ import annotations

import re
import shutil
import time
from importlib import resources
from pathlib import Path
from typing import Callable

import jinja2

from ..fileio import write_text
from ..i18n import tr
from ..publish import make_staging, publish
from ..results import dumps
from .fmt import md_text, meta_text
from .titlebreak import SUBTITLE_SIZE, TITLE_SIZE, title_markdown
from .parallel import background_saves

FORMATS = ("md", "pdf", "docx", "dxf", "gif")


def template_dir(override: Path | None = None) -> Path:
    """The report templates: ``override`` or the ``templates/`` shipped with mechdesign."""
    if override is not None:
        return Path(override)
    return Path(str(resources.files("mechdesign.templates")))


class _LanguageLoader(jinja2.FileSystemLoader):
    """Templates by name, a language's own version first: "cam_section.md.j2" is served
    from "cam_section.<lang>.md.j2" when that exists (a template whose structure differs
    between the languages, or a student's override for one language), else the shared
    "cam_section.md.j2", whose words come from the catalogues (``{{ _("…") }}``)."""

    def __init__(self, folder: str, lang: str):
        super().__init__(folder)
        self.lang = lang

    def get_source(self, environment, template):
        if template.endswith(".md.j2") and template.count(".") == 2:
            own = template[:-len(".md.j2")] + f".{self.lang}.md.j2"
            try:
                return super().get_source(environment, own)
            except jinja2.TemplateNotFound:
                pass
        parts = template.split(".")
        if len(parts) == 4 and parts[1] in ("zh", "en") and template.endswith(".md.j2"):
            try:                # an older name "x.zh.md.j2" of a shared template
                return super().get_source(environment, template)
            except jinja2.TemplateNotFound:
                return super().get_source(environment, f"{parts[0]}.md.j2")
        return super().get_source(environment, template)


def cited(sentence: str, citation: str) -> str:
    """``sentence`` with ``citation`` (``\\[7, 9\\]``) set before its closing stop, as a
    citation stands everywhere else ("…重新校核[7, 9]。", "… checked again [7, 9]."), not
    after it; a sentence that ends otherwise (a formula, a colon) takes it at its end."""
    if not citation:
        return sentence
    body = sentence.rstrip()
    if body.endswith("。"):
        return body[:-1] + citation + "。"
    if body.endswith("."):
        return body[:-1] + " " + citation + "."
    return sentence + citation


def render_markdown(template_name: str, ctx: dict, templates: Path,
                    lang: str | None = None) -> str:
    """Render a report template in Jinja's sandbox: a user's ``--templates`` folder can
    format the prepared values but cannot reach Python (no ``__class__``, no imports, no
    calls of unsafe methods); what it tries is a rendering error, not code run.

    ``lang`` (zh or en; by default read from a name such as "shaper.zh.md.j2") picks each
    template's language version (:class:`_LanguageLoader`) and the catalogue of
    ``{{ _("…") }}`` (:mod:`mechdesign.i18n`; a variant such as zh_TW set for the run
    is used for its base language)."""
    from jinja2.sandbox import SandboxedEnvironment

    from ..i18n import jinja_callables
    from .labels import md_symbols

    if lang is None:
        lang = "zh" if ".zh." in template_name else "en"
    # Pandoc's attribute syntax "{#fig:x}" would open a Jinja comment: comments are {## ##}.
    env = SandboxedEnvironment(loader=_LanguageLoader(str(templates), lang),
                             undefined=jinja2.StrictUndefined, autoescape=False,
                             keep_trailing_newline=True, extensions=["jinja2.ext.i18n"],
                             comment_start_string="{##", comment_end_string="##}",
                             bytecode_cache=_bytecode_cache())
    env.install_gettext_callables(**jinja_callables(lang), newstyle=True)
    env.filters["figlabel"] = figure_label
    env.filters["symbols"] = md_symbols     # a table cell's quantity letters as math
    env.filters["cited"] = cited            # a citation inside the sentence, before its stop
    if "cite" not in ctx:      # the citation counter (render/summary.py), one per report
        from .summary import Citations

        ctx = {**ctx, "cite": Citations(lang)}
    return env.get_template(template_name).render(**ctx)


def figure_label(path: str) -> str:
    """The cross-reference label of a figure named after its file ("figures/linkage_graph_4_kin.png"
    -> "fig:linkage-graph-4-kin"): figures drawn per position or per linkage are cited by it."""
    stem = str(path).rsplit("/", 1)[-1].rsplit(".", 1)[0]
    return "fig:" + (re.sub(r"[^A-Za-z0-9]+", "-", stem).strip("-") or "figure")


def _bytecode_cache():
    """The templates compiled once, kept in the render cache's folder (render/cache.py;
    Jinja keys each by its name and a checksum of its source); None when caching is off."""
    from . import cache

    where = cache.folder()
    if where is None:
        return None
    try:
        (where / "jinja").mkdir(parents=True, exist_ok=True)
    except OSError:
        return None
    return jinja2.FileSystemBytecodeCache(str(where / "jinja"))


def group_banner(group: str, lang: str) -> str:
    """The line atop a report computed for one data group of its brief (the label is
    user text: escaped so that it shows as written)."""
    group = md_text(group)
    _ = tr(lang)
    return _("**Data group: {group}.** This report uses that group's data from the "
             "design brief's table of data groups.", group=group) + "\n\n"


def pdf_metadata(meta, lang: str, group: str | None = None) -> dict:
    """Title-page metadata for templates/report.typ (and the Word title block) from the
    brief's report section. pandoc reads metadata strings as Markdown: the user's text is
    escaped (:func:`~.fmt.md_text`) so that it shows as written. The date also dates the
    PDF and the Word file (:func:`.pdf.source_timestamp`), so that a brief renders the
    same bytes every time."""
    data = {"title": md_text(meta_text(meta, "title", lang)),
            "subtitle": md_text(meta_text(meta, "subtitle", lang)),
            "student": md_text(meta.student), "student_id": md_text(meta.student_id),
            "class": md_text(meta.class_name), "teacher": md_text(meta.teacher),
            "date": md_text(meta.date), "lang": lang,
            # PDF/Word document properties: subject = the report's title (and subtitle);
            # the author is the student (templates/report.typ, render/docx.py)
            "description": md_text(" — ".join(t for t in (meta_text(meta, "title", lang),
                                                          meta_text(meta, "subtitle", lang)) if t))}
    # the title page's lines: balanced, broken at phrase boundaries (render/titlebreak.py)
    title, subtitle = meta_text(meta, "title", lang), meta_text(meta, "subtitle", lang)
    for key, text, size in (("cover-title", title, TITLE_SIZE), ("cover-subtitle", subtitle, SUBTITLE_SIZE)):
        if text:
            data[key] = title_markdown(text, lang, size)
    if group is not None:
        data["group"] = md_text(group)
    if lang == "en":
        # Latin text in a Latin face (typst ships Libertinus Serif); CJK names and titles
        # fall back to the Chinese serif, whose punctuation is full-width.
        from .fonts import cjk_families

        data["mainfont"] = ["Libertinus Serif", cjk_families()["serif"]]
    return data


PROGRESS_EVERY = 1.5     # [s] the longest a rendering step goes without a progress line


def write_report(out_dir: Path, *, machine: str, lang: str, formats: tuple[str, ...],
                 make_figures: Callable[[Path], dict], make_context: Callable[[dict], dict],
                 document: dict, meta, templates: Path | None = None,
                 progress: Callable[[str], None] | None = None,
                 write_data: Callable[[Path], list] | None = None,
                 make_sheets: Callable[[Path, Path], Callable[[], list]] | None = None,
                 animate: Callable[[Path], Path] | None = None,
                 group: str | None = None, parallel: bool = False,
                 program: dict | None = None) -> list[Path]:
    """Render into a staging folder, then move the finished files into ``out_dir``.

    ``write_data`` may add machine-specific data files (e.g. CSV coordinates) to the folder;
    ``make_sheets(folder, fig_dir)`` writes the drawing sheets and returns a function
    giving their :class:`~.sheets.SheetFiles`; ``animate(path)`` writes the GIF (format gif);
    ``group`` (a data group of the brief) is stated on the title page and atop the report;
    ``parallel`` lets figures and sheets be written by a helper process while the next one
    is drawn (:mod:`.parallel`: a single run on a machine of two cores or more);
    ``program`` ({stages: titles of the stages that ran, module: the stages module}) adds
    the appendix with the analysis program's flow chart and listing (:mod:`.summary`)."""
    told = [time.monotonic()]

    def say(msg: str) -> None:
        told[0] = time.monotonic()
        if progress is not None:
            progress(msg)

    def figure_drawn(label: str) -> None:
        # a step that runs long (the figures of a large run) still shows progress: a line
        # naming the figure at hand once PROGRESS_EVERY seconds have passed without one
        if time.monotonic() - told[0] >= PROGRESS_EVERY:
            say(f"figures: {label}")

    tdir = template_dir(templates)
    out_dir = Path(out_dir)
    staging = make_staging(out_dir)
    try:
        fig_dir = staging / "figures"
        fig_dir.mkdir()
        # Figures and sheets may be saved later or by a helper process until the block
        # ends (:mod:`.parallel`); the Markdown, the data files and pandoc need only their
        # names, so pandoc runs while the last of them are written. The sheets first: they
        # are the largest pieces, and a large piece left to the end would keep one core
        # busy while the other waits.
        pending = None
        try:
            with background_saves(parallel, on_save=figure_drawn):
                collect_sheets = (make_sheets(staging, fig_dir) if make_sheets is not None
                                  else (lambda: []))
                say("figures")
                figures = make_figures(fig_dir)
                sheets = collect_sheets()
                ctx = make_context(figures)
                ctx.update(sheets_context([_sheet_row(sh, lang) for sh in sheets], lang,
                                          dxf=any(sh.dxf for sh in sheets)))
                from .summary import Citations, handin_context

                ctx.update(handin_context(machine, document, ctx, lang, meta_text(meta, "title", lang),
                                           program, fig_dir),
                           cite=Citations(lang))
                say("Markdown")
                md = render_markdown(f"{machine}.md.j2", ctx, tdir, lang)
                if group is not None:
                    md = group_banner(group, lang) + md
                write_text(staging / "report.md", md, encoding="utf-8")
                write_text(staging / "results.json", dumps(document), encoding="utf-8")
                if "pdf" in formats:
                    from .pdf import typst_source

                    say("PDF: Markdown → typst (pandoc, in the background)")
                    pending = typst_source(staging / "report.md", pdf_metadata(meta, lang, group),
                                           tdir / "report.typ")
                if write_data is not None:
                    say("data files (CSV)")
                    write_data(staging)
                say("figures and sheets: the last ones")
            say("figures and sheets: all written")
            if pending is not None:
                from .pdf import compile_pdf

                source = pending.result()
                say("PDF: typst → report.pdf")
                # the PDF places each drawing sheet as vector graphics (its own PDF)
                vector = {sh.preview: sh.pdf for sh in sheets if sh.pdf}
                compile_pdf(source, staging, staging / "report.pdf",
                            pdf_metadata(meta, lang, group), vector)
        finally:
            if pending is not None:
                pending.cancel()
        if "docx" in formats:
            say("Word (pandoc → docx)")
            from .docx import render_docx

            render_docx(staging / "report.md", staging / "report.docx",
                        pdf_metadata(meta, lang, group), tdir)
        if "gif" in formats and animate is not None:
            say("animation (GIF)")
            animate(staging / "animation.gif")
        if "md" not in formats:
            (staging / "report.md").unlink()
        return publish(staging, out_dir)
    finally:
        shutil.rmtree(staging, ignore_errors=True)


def sheets_context(rows: list[dict], lang: str, dxf: bool = False) -> dict:
    """The sheets chapter's context: the sheets' rows (:func:`_sheet_row`), how the A1
    analysis sheet's polygons are scaled (no force polygons on a kinematics-only sheet), the
    previews' figure references, and whether the run wrote the sheets as DXF too (``dxf``:
    the text describes the DXF files' layers only where there are files; page review 47)."""
    _ = tr(lang)
    note = ""
    for row in rows:
        if row["label"] != "fig:sheet-analysis":
            continue
        if row.get("kinematic_only"):
            note = _(" On the A1 analysis sheet every velocity and acceleration polygon is drawn to fill "
                     "its cell, at its own scale written above it ($\\mu_v$, $\\mu_a$), not at the "
                     "scales of the report's figures.")
        else:
            note = _(" On the A1 analysis sheet every velocity, acceleration and force polygon is drawn "
                     "to fill its cell, at its own scale written above it ($\\mu_v$, $\\mu_a$, "
                     "$\\mu_F$), not at the scales of the report's figures.")
    previews = _.pgettext("list", ", ").join("@" + row["label"] for row in rows)
    return {"sheets": rows, "sheets_note": note, "sheet_previews": previews, "sheets_dxf": dxf}


def _sheet_row(sh, lang: str) -> dict:
    """Strings the templates show for one sheet (a report names a drawing by its title,
    size and scale; the file names are the hand-in's, not the report's)."""
    return {"title": sh.title, "size": sh.size, "scale": sh.scale, "preview": sh.preview,
            "label": f"fig:sheet-{sh.name}", "kinematic_only": getattr(sh, "kinematic_only", False)}

"""Every figure of every report is cited in its text (review35 item 10: a teacher marks
"图未在正文中引用", and a figure that floated a page away cannot be found).

The Markdown of every example brief in both languages (tests/test_report_prose.py builds it
without figures or PDF) defines each figure with a pandoc-crossref label ``{#fig:x}``; the
text outside the figure's own caption must name it at least once as ``@fig:x`` (typst and
the Word filter turn that into "图 N" / "Figure N"). The drawing-sheet previews, left out of
that Markdown, are checked on the sheets chapter itself.
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

_FIGURE = re.compile(r"^!\[.*\]\([^)]*\)\{#(fig:[^\s}]+)[^}]*\}\s*$", re.M)
_LABEL = re.compile(r"\{#(fig:[^\s}]+)")
_CITE = re.compile(r"@(fig:[\w:.\-]*\w)")


def uncited(md: str) -> list[str]:
    """The figure labels of ``md`` that no text outside the figure lines cites, in order."""
    defined = _LABEL.findall(md)
    text = _FIGURE.sub(" ", md)          # a figure's own caption does not count
    cited = set(_CITE.findall(text))
    return [label for label in defined if label not in cited]


def test_uncited_reads_labels_and_citations():
    md = ("Text @fig:a and [@fig:b].\n\n![cap @fig:c](x.png){#fig:c width=50%}\n\n"
          "![A](a.png){#fig:a}\n\n![B](b.png){#fig:b width=9%}\n")
    assert uncited(md) == ["fig:c"]


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_figure_is_cited_in_the_text(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    labels = _LABEL.findall(md)
    assert len(labels) == len(set(labels)), "a figure label is defined twice"
    assert not uncited(md)
    # each figure line is a figure: every image carries a label
    images = re.findall(r"^!\[", md, flags=re.M)
    assert len(images) == len(labels)


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_sheet_previews_are_cited(lang):
    from mechdesign.render.report import render_markdown, sheets_context, template_dir
    from mechdesign.render.summary import Citations

    sheets = [{"title": f"S{i}", "size": "A3", "scale": "1:1", "preview": f"figures/s{i}.png",
               "label": label}
              for i, label in enumerate(["fig:sheet-kinematic", "fig:sheet-analysis"])]
    md = render_markdown("sheets_section.md.j2", {**sheets_context(sheets, lang), "cite": Citations(lang)},
                         template_dir(None), lang)
    assert _LABEL.findall(md) == ["fig:sheet-kinematic", "fig:sheet-analysis"]
    assert not uncited(md)


def test_figure_labels_from_file_names():
    from mechdesign.render.report import figure_label

    assert figure_label("figures/linkage_graph_4_kin.png") == "fig:linkage-graph-4-kin"
    assert figure_label("figures/press_graph_8p_f0.png") == "fig:press-graph-8p-f0"

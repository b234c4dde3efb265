"""Small defects of the Word report that review 38 found (LibreOffice's layout of the .docx):

* "57.04 mm ,b": a display formula broken at its ``\\quad`` into aligned lines
  (render/docx_math) is set by LibreOffice as the lines one after another, without the space
  the ``\\quad`` was — each line but the last now ends in an em space;
* a lone "）" at the start of a line after an inline formula (the cam laws' "(peak
  coefficients $C_v = …, C_j = 60.00$)", die_cutter zh's data table "（$J \\propto 1/n^2$）"):
  a closing mark right after an inline formula goes into the formula;
* the last page of die_cutter en held three references alone: a short reference list is kept
  with its heading on one page.
"""
from __future__ import annotations

import re

from mechdesign.render.docx_layout import (REFERENCES_LAST, REFERENCES_WHOLE,
                                           keep_closing_marks_with_formulas, keep_references_together)
from mechdesign.render.docx_math import align_broken_equations

M = '<m:r><m:t>{}</m:t></m:r>'


def _aligned(*rows: str) -> str:
    body = "".join(f"<m:e>{M.format('&amp;')}{row}</m:e>" for row in rows)
    return f'<m:oMathPara><m:oMathParaPr><m:jc m:val="center" /></m:oMathParaPr><m:oMath><m:eqArr>{body}</m:eqArr></m:oMath></m:oMathPara>'


def test_a_broken_formula_keeps_a_space_between_its_lines():
    xml = _aligned(M.format("a") + M.format("=57.04,"), M.format("b") + M.format("=157.97"))
    out = align_broken_equations(xml)
    lines = re.findall(r"<m:oMath>(.*?)</m:oMath>", out, re.S)
    assert len(lines) == 2
    # the first line ends in a space (then the break), the last has neither
    assert re.search(r'<m:t xml:space="preserve">\u2003</m:t></m:r><m:r><w:br /></m:r>$', lines[0])
    assert "\u2003" not in lines[1] and "w:br" not in lines[1]


def test_a_closing_mark_after_an_inline_formula_stays_with_it():
    text = ('<w:p><w:r><w:t>（峰值系数 </w:t></w:r><m:oMath>' + M.format("C_j=60.00") +
            '</m:oMath><w:r><w:t xml:space="preserve">）。下一句</w:t></w:r></w:p>')
    out = keep_closing_marks_with_formulas(text)
    assert "<m:t>）。</m:t></m:r></m:oMath>" in out
    assert '<w:t xml:space="preserve">下一句</w:t>' in out
    # an opening bracket right before the formula goes into its start
    before = '<w:r><w:t xml:space="preserve">转动惯量小（</w:t></w:r><m:oMath>' + M.format("J") + '</m:oMath>'
    assert keep_closing_marks_with_formulas(before) == (
        '<w:r><w:t xml:space="preserve">转动惯量小</w:t></w:r><m:oMath><m:r><m:rPr><m:nor /><m:sty m:val="p" />'
        '</m:rPr><m:t>（</m:t></m:r>' + M.format("J") + '</m:oMath>')
    # an opening bracket or a word after the formula stays where it is; a display formula too
    for same in ('<m:oMath>' + M.format("x") + '</m:oMath><w:r><w:t>（a）</w:t></w:r>',
                 '<m:oMathPara><m:oMath>' + M.format("x") + '</m:oMath><w:r><w:t>）</w:t></w:r></m:oMathPara>'):
        assert keep_closing_marks_with_formulas(same) == same


def _references(n: int) -> str:
    heading = '<w:p><w:pPr><w:pStyle w:val="Heading1" /></w:pPr><w:r><w:t>References</w:t></w:r></w:p>'
    entries = "".join(f'<w:p><w:pPr><w:pStyle w:val="BodyText" /></w:pPr><w:r><w:t>[{k}] x</w:t></w:r></w:p>'
                      for k in range(1, n + 1))
    return ('<w:body><w:bookmarkStart w:id="7" w:name="references" />' + heading + entries
            + '<w:bookmarkEnd w:id="7" /><w:sectPr /></w:body>')


def _kept_entries(xml: str) -> list[bool]:
    return ["<w:keepNext />" in p for p in re.findall(r"<w:p>.*?</w:p>", xml)]


def test_a_short_reference_list_is_kept_with_its_heading():
    kept = _kept_entries(keep_references_together(_references(11)))
    assert kept == [True] * 11 + [False]          # heading and [1]…[10] kept with the next
    assert _kept_entries(_references(11)) == [False] * 12          # the old XML: nothing kept
    long = _kept_entries(keep_references_together(_references(REFERENCES_WHOLE + 5)))
    assert long == [False] * (len(long) - REFERENCES_LAST) + [True] * (REFERENCES_LAST - 1) + [False]
    # the schema's order: pStyle, keepNext, keepLines
    assert ('<w:pPr><w:pStyle w:val="BodyText" /><w:keepNext /><w:keepLines /></w:pPr>'
            in keep_references_together(_references(3)))

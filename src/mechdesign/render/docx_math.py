"""Formulas of the Word report in forms that Word and LibreOffice both read: broken display
formulas as aligned lines (:func:`align_broken_equations`), a bracket closed in a script's
base as a delimiter (:func:`group_scripted_brackets`, below).

A formula too wide for a line is set by render/mathbreak as ``\\begin{aligned} … \\end{aligned}``,
one ``&`` per line. pandoc (texmath) writes it as an equation array ``m:eqArr`` whose
alignment marks are literal ``&`` characters in the math text: Word's own form (ISO/IEC 29500-1
§22.1.2.34; MS-OE376 on eqArr: odd ``&`` are alignment points). LibreOffice's OMML import turns
``m:eqArr`` into a StarMath ``stack`` and the text ``&`` into StarMath's logical-and operator,
drawn "∧" with an error mark "¿" for its missing operand (starmath/source/ooxmlimport.cxx).

:func:`align_broken_equations` rewrites each such math paragraph as the other form Word has
for aligned lines: one ``m:oMath`` per line in the same ``m:oMathPara``, each line but the
last ended by a line break ``<m:r><w:br/></m:r>`` (Word merges adjacent equations that no
``w:br`` separates, MS-OE376 §7.1.2.77), the alignment point marked by ``m:aln`` in the run
properties of the run that followed the ``&`` (Word applies ``aln`` to math runs,
MS-OI29500 §22.1.2.3; a structure after the ``&`` gets an empty run before it that carries
the mark), and the math paragraph justified ``centerGroup`` (the lines centred as a group).

LibreOffice reads each ``m:oMath`` as an inline formula of its own and ignores ``m:aln`` and
the break run: it wraps the lines at the cell's width, so two short lines may share a row
there. A line that starts with a relation or operator (``= 1124.27 − …``) gets an empty
normal-text run before it, which Word draws as nothing and which gives StarMath's binary
operator the left operand it needs (else "¿"); a bracket whose partner is on another line is
set as normal text (else "¿" too).
"""
from __future__ import annotations

import re

#: The alignment mark texmath writes between the columns of an ``aligned`` row.
_AMPERSAND = "<m:r><m:t>&amp;</m:t></m:r>"
#: Line break between the equations of a math paragraph (Word's form).
_LINE_BREAK = "<m:r><w:br /></m:r>"
#: The space that ends each line but the last (the ``\\quad`` render/mathbreak broke the formula
#: at): Word draws it at the end of the line as nothing, LibreOffice, which sets the lines
#: one after another, as the space between them ("57.04 mm, b = …", never "57.04 mm,b").
_LINE_END_SPACE = '<m:r><m:rPr><m:nor /></m:rPr><m:t xml:space="preserve">\u2003</m:t></m:r>'
#: An empty normal-text run: LibreOffice's operand before a line that starts with an operator.
_EMPTY_OPERAND = "<m:r><m:rPr><m:nor /></m:rPr><m:t></m:t></m:r>"
#: Characters that need a left operand in StarMath (relations, arrows, binary operators
#: other than the unary-capable + − ±).
_NEEDS_LEFT = set("=<>≤≥≈≠≡∼≃⇒⇐⇔→×⋅·∕/")

_PARA = re.compile(r"<m:oMathPara>.*?</m:oMathPara>", re.DOTALL)
_ONLY_ARRAY = re.compile(r"<m:oMath><m:eqArr>(.*)</m:eqArr></m:oMath>", re.DOTALL)
_ARG_TAG = re.compile(r"<(/?)m:e>")
#: a math run's properties: empty elements only (m:sty, m:nor, m:aln …), so that a match
#: never runs on into the next run
_PROPS = r"(?:<m:rPr>((?:<m:\w+[^>]*/>)*)</m:rPr>)?"
_RUN_START = re.compile(r"<m:r>" + _PROPS)
_RUN_TEXTS = re.compile(r"<m:r>" + _PROPS + r"<m:t(?: [^>]*)?>([^<]*)</m:t></m:r>")


def _array_rows(inner: str) -> list[str] | None:
    """Contents of the top-level ``m:e`` arguments of an ``m:eqArr`` body, or None if the body
    holds anything else at the top (``m:eqArrPr``)."""
    rows: list[str] = []
    depth = 0
    start = 0
    last_end = 0
    for tag in _ARG_TAG.finditer(inner):
        if tag.group(1) == "":
            if depth == 0:
                if inner[last_end:tag.start()].strip():
                    return None
                start = tag.end()
            depth += 1
        else:
            depth -= 1
            if depth == 0:
                rows.append(inner[start:tag.start()])
                last_end = tag.end()
    if depth != 0 or inner[last_end:].strip() or not rows:
        return None
    return rows


def _with_alignment_point(rest: str) -> str:
    """``rest`` (a line after its ``&``) with its first element marked as the alignment point:
    a run carries ``m:aln`` itself; before a structure (``F⃗ᵗ₂₃ + …``) stands an empty run
    that carries it (the standard's other carrier, an operator-emulator box, would give the
    structure an operator's spacing)."""
    run = _RUN_START.match(rest)
    if run is not None:
        props = run.group(1) or ""
        # m:aln is the last child of m:rPr (CT_RPR: lit?, (nor | scr?, sty?), brk?, aln?)
        return f"<m:r><m:rPr>{props}<m:aln /></m:rPr>" + rest[run.end():]
    return "<m:r><m:rPr><m:aln /></m:rPr><m:t></m:t></m:r>" + rest


def _starts_with_operator(line: str) -> bool:
    """Whether the first visible text of ``line`` is a run whose text begins with an operator
    that needs a left operand (space-only runs skipped)."""
    pos = 0
    while True:
        run = _RUN_TEXTS.match(line, pos)
        if run is None:
            return False
        text = run.group(2).strip()
        if text:
            return text[0] in _NEEDS_LEFT
        pos = run.end()


_BRACKET_RUN = re.compile(r"<m:r>" + _PROPS + r"<m:t>([()\[\]])</m:t></m:r>")
_OPENING = {")": "(", "]": "["}


def _unmatched_brackets_as_text(line: str) -> str:
    """``line`` with the bracket runs that have no partner in it (a bracket pair the break
    split over two lines) set as normal text (``m:nor``): LibreOffice reads each line as a
    formula of its own and draws an error mark "¿" at an unbalanced bracket, but quotes
    normal text; Word draws either the same bracket."""
    runs = list(_BRACKET_RUN.finditer(line))
    stack: list[int] = []
    unmatched: set[int] = set()
    for n, run in enumerate(runs):
        char = run.group(2)
        if char in "([":
            stack.append(n)
        elif stack and runs[stack[-1]].group(2) == _OPENING[char]:
            stack.pop()
        else:
            unmatched.add(n)
    unmatched.update(stack)
    for n in sorted(unmatched, reverse=True):
        run = runs[n]
        aln = "<m:aln />" if "<m:aln />" in (run.group(1) or "") else ""
        text = f"<m:r><m:rPr><m:nor />{aln}</m:rPr><m:t>{run.group(2)}</m:t></m:r>"
        line = line[:run.start()] + text + line[run.end():]
    return line


def _line(row: str) -> str:
    """One ``aligned`` row (an ``m:e`` body) as the content of an ``m:oMath``."""
    mark = row.find(_AMPERSAND)
    if mark < 0:
        line = row
    else:
        head, rest = row[:mark], row[mark + len(_AMPERSAND):].replace(_AMPERSAND, "")
        line = head + (_with_alignment_point(rest) if rest else "")
    if _starts_with_operator(line):
        line = _EMPTY_OPERAND + line
    return _unmatched_brackets_as_text(line)


def _paragraph(match: re.Match) -> str:
    para = match.group(0)
    array = _ONLY_ARRAY.search(para)
    rows = _array_rows(array.group(1)) if array is not None else None
    if rows is None or _AMPERSAND not in array.group(1):
        return para
    lines = [_line(row) for row in rows]
    maths = "".join(f"<m:oMath>{line}{_LINE_END_SPACE + _LINE_BREAK if n < len(lines) - 1 else ''}</m:oMath>"
                    for n, line in enumerate(lines))
    head = para[:array.start()].replace('<m:jc m:val="center" />', '<m:jc m:val="centerGroup" />')
    return head + maths + para[array.end():]


def align_broken_equations(document_xml: str) -> str:
    """``word/document.xml`` with every math paragraph that consists of one aligned equation
    array (``m:eqArr`` with ``&`` marks, as pandoc writes ``aligned``) rewritten as aligned
    lines (see the module docstring); everything else unchanged."""
    if _AMPERSAND not in document_xml:
        return document_xml
    return _PARA.sub(_paragraph, document_xml)




# ---- a bracket closed in a script's base: (a + b)² ------------------------------------------
#
# texmath writes (a + b)² as the runs "(", a, +, b followed by a superscript whose base is the
# run ")" alone. Word draws that as it reads; LibreOffice converts every argument to a StarMath
# group of its own, so the "(" outside and the ")" inside the superscript's group are each
# unbalanced and drawn "¿". :func:`group_scripted_brackets` makes the bracketed run the
# script's base as a delimiter object (m:d), Word's own form of (a + b)², which LibreOffice
# imports as "left( a + b right)^2". Bars "|" in pairs become absolute values the same way,
# and a superscript asterisk (h_a^*) the asterisk operator U+2217.

_M = "http://schemas.openxmlformats.org/officeDocument/2006/math"
_W = "http://schemas.openxmlformats.org/wordprocessingml/2006/main"
_SCRIPTS = {f"{{{_M}}}sSup", f"{{{_M}}}sSub", f"{{{_M}}}sSubSup"}
_CLOSING = {")": "(", "]": "["}
_OMATH = re.compile(r"<m:oMath>.*?</m:oMath>", re.DOTALL)


def _bracket(element) -> str | None:
    """The text of a math run that is one bracket (or bar) and nothing else, else None."""
    if element.tag != f"{{{_M}}}r":
        return None
    texts = [t.text or "" for t in element.iter(f"{{{_M}}}t")]
    text = "".join(texts).strip()
    return text if len(texts) == 1 and text in ("(", ")", "[", "]", "|") else None


def _delimited(children, begin: str, end: str):
    """A delimiter object (m:d) with ``begin`` and ``end`` around ``children``."""
    from xml.etree import ElementTree as ET

    delimiter = ET.Element(f"{{{_M}}}d")
    props = ET.SubElement(delimiter, f"{{{_M}}}dPr")
    ET.SubElement(props, f"{{{_M}}}begChr", {f"{{{_M}}}val": begin})
    ET.SubElement(props, f"{{{_M}}}endChr", {f"{{{_M}}}val": end})
    inner = ET.SubElement(delimiter, f"{{{_M}}}e")
    inner.extend(children)
    return delimiter


def _pair_bars(parent) -> bool:
    """Bar runs "|" of ``parent``, when there is an even number of them, taken in pairs as
    absolute values |x| (m:d): StarMath reads a bare "|" as the logical or "∨"."""
    children = list(parent)
    bars = [n for n, child in enumerate(children) if _bracket(child) == "|"]
    if not bars or len(bars) % 2:
        return False
    for start, end in reversed(list(zip(bars[::2], bars[1::2]))):
        inside = children[start + 1:end]
        for element in children[start:end + 1]:
            parent.remove(element)
        parent.insert(start, _delimited(inside, "|", "|"))
        children = list(parent)
    return True


def _closing_base(element) -> str | None:
    """The bracket that is the whole base of a script element (its m:e), else None."""
    if element.tag not in _SCRIPTS:
        return None
    base = element.find(f"{{{_M}}}e")
    if base is None or len(base) != 1:
        return None
    char = _bracket(base[0])
    return char if char in _CLOSING or char == "|" else None


def _group(parent) -> bool:
    """Rewrites ``parent``'s children (and theirs); True if anything changed."""
    changed = False
    for child in list(parent):
        changed |= _group(child)
    children = list(parent)
    k = 0
    while k < len(children):
        closing = _closing_base(children[k])
        if closing is None:
            k += 1
            continue
        depth, j = 0, k - 1
        while j >= 0:
            char = _bracket(children[j])
            if closing == "|":
                if char == "|":
                    break
            elif char == closing:
                depth += 1
            elif char == _CLOSING[closing]:
                if depth == 0:
                    break
                depth -= 1
            j -= 1
        if j < 0:
            k += 1
            continue
        script = children[k]
        base = script.find(f"{{{_M}}}e")
        inside = children[j + 1:k]
        for element in children[j:k]:
            parent.remove(element)
        base[:] = [_delimited(inside, _CLOSING.get(closing, closing), closing)]
        children = list(parent)
        k = children.index(script) + 1
        changed = True
    return _pair_bars(parent) or changed


#: a superscript that is an asterisk alone (h_a^*, c^*): StarMath reads "*" as an operator
#: and draws "¿" for its operands; U+2217 (asterisk operator) is a symbol to both readers
_STAR_SUPERSCRIPT = re.compile(r"(<m:sup><m:r>(?:<m:rPr>(?:<m:\w+[^>]*/>)*</m:rPr>)?<m:t>)\*(</m:t></m:r></m:sup>)")


def group_scripted_brackets(document_xml: str) -> str:
    """``word/document.xml`` with every ``(…)ⁿ`` that texmath wrote as a bracket run and a
    script whose base is the closing bracket rewritten as a script of a delimiter object."""
    from xml.etree import ElementTree as ET

    ET.register_namespace("m", _M)
    ET.register_namespace("w", _W)
    head = f'<root xmlns:m="{_M}" xmlns:w="{_W}">'

    def one(match: re.Match) -> str:
        fragment = match.group(0)
        if "<m:sSu" not in fragment and "<m:t>|</m:t>" not in fragment:
            return fragment
        root = ET.fromstring(head + fragment + "</root>")
        if not _group(root):
            return fragment
        text = ET.tostring(root, encoding="unicode")
        return text[text.index(">") + 1:text.rindex("</root>")]

    grouped = _OMATH.sub(one, document_xml)
    return _STAR_SUPERSCRIPT.sub(lambda m: m.group(1) + "\u2217" + m.group(2), grouped)


__all__ = ["align_broken_equations", "group_scripted_brackets"]

"""Maintain the translation catalogues (src/mechdesign/locale/*.po) with Babel.

    python tools/i18n.py check            # every marked string has its Chinese; none obsolete
    python tools/i18n.py add MSGID MSGSTR [--context C]
    python tools/i18n.py add-json pairs.json   # [[msgid, msgstr] or [msgid, msgstr, context], ...]
    python tools/i18n.py prune            # drop entries no code or template uses any more
    python tools/i18n.py tw               # regenerate zh_TW.po from zh.po (OpenCC s2twp), and
                                          # zh_TW.data.json: the data tables' *_zh texts converted
    python tools/i18n.py union A.po B.po  # after a merge conflict: the union of two versions → zh.po

The msgid is the program's English text. Strings are found by Babel's extractors in
src/mechdesign (``_("…")``, ``_.pgettext("ctx", "…")``, ``N_("…")``, ``gettext``) and in
templates/ (``{{ _("…") }}``, ``{% trans %}``). The catalogues are written sorted, unwrapped
and without source locations, so that two branches adding messages merge line by line.
"""
from __future__ import annotations

import json
import sys
from io import BytesIO
from pathlib import Path

from babel.messages.catalog import Catalog
from babel.messages.extract import extract_from_dir
from babel.messages.mofile import write_mo
from babel.messages.pofile import read_po, write_po

ROOT = Path(__file__).resolve().parents[1]
LOCALE = ROOT / "src" / "mechdesign" / "locale"
KEYWORDS = {"_": None, "N_": None, "gettext": None, "ngettext": (1, 2),
            "pgettext": ((1, "c"), 2)}
JINJA_OPTIONS = {"comment_start_string": "{##", "comment_end_string": "##}",
                 "extensions": "jinja2.ext.i18n", "newstyle_gettext": "true"}


def extracted() -> dict[tuple[str | None, str], list[str]]:
    """{(context, msgid): [where, …]} of every string marked in the code and templates."""
    found: dict[tuple[str | None, str], list[str]] = {}
    sources = [(ROOT / "src" / "mechdesign", [("**.py", "python")], {}),
               (ROOT / "templates", [("**.j2", "jinja2.ext:babel_extract")],
                {"**.j2": JINJA_OPTIONS})]
    for folder, method_map, options in sources:
        for filename, lineno, message, _comments, context in extract_from_dir(
                str(folder), method_map=method_map, options_map=options, keywords=KEYWORDS):
            msgid = message[0] if isinstance(message, (tuple, list)) else message
            if not msgid:
                continue
            found.setdefault((context, msgid), []).append(f"{folder.name}/{filename}:{lineno}")
    return found


def load(name: str) -> Catalog:
    path = LOCALE / f"{name}.po"
    with path.open("rb") as fh:
        return read_po(fh, locale=name, domain="mechdesign")


def save(cat: Catalog, name: str) -> None:
    buf = BytesIO()
    write_po(buf, cat, width=0, no_location=True, omit_header=False, sort_output=True,
             ignore_obsolete=True)
    (LOCALE / f"{name}.po").write_bytes(buf.getvalue())
    compile_mo(name)


def compile_mo(name: str) -> bytes:
    """Compile ``<name>.po`` into ``<name>.mo`` (what the program reads at run time, with
    the standard library's gettext: no Babel needed to run); return its bytes."""
    buf = BytesIO()
    write_mo(buf, load(name), use_fuzzy=False)
    (LOCALE / f"{name}.mo").write_bytes(buf.getvalue())
    return buf.getvalue()


def problems() -> tuple[list[str], list[str]]:
    """(missing, obsolete): marked strings zh.po lacks, zh.po entries nothing uses."""
    found = extracted()
    cat = load("zh")
    have = {(m.context, m.id): m.string for m in cat if m.id}
    missing = [f"{where[0]}: {msgid!r}" + (f" (context {ctx!r})" if ctx else "")
               for (ctx, msgid), where in sorted(found.items(), key=lambda kv: kv[1][0])
               if not have.get((ctx, msgid))]
    obsolete = [repr(k[1]) + (f" (context {k[0]!r})" if k[0] else "")
                for k in have if k not in found]
    return missing, obsolete


def add(pairs: list[list[str]]) -> int:
    cat = load("zh")
    clashes = 0
    for item in pairs:
        msgid, msgstr = item[0], item[1]
        context = item[2] if len(item) > 2 else None
        old = cat.get(msgid, context=context)
        if old is not None and old.string and old.string != msgstr:
            print(f"clash: {msgid!r}" + (f" [{context}]" if context else "") +
                  f" is already {old.string!r}, not {msgstr!r}: give one of them a context "
                  f"(_.pgettext(context, msgid))", file=sys.stderr)
            clashes += 1
            continue
        cat.add(msgid, msgstr, context=context)
    save(cat, "zh")
    return 1 if clashes else 0


def data_texts() -> set[str]:
    """The Chinese texts of the shipped data tables that a report shows: every value of a
    ``*_zh`` key of ``src/mechdesign/data/*.yaml`` and of a ``*_zh`` column of its CSV files
    (names of materials, transmissions, load classes …; the references keep the titles as
    published). Converted for zh_TW into ``locale/zh_TW.data.json`` by ``tw``."""
    import csv

    import yaml

    out: set[str] = set()

    def walk(node, key=""):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, str(k))
        elif isinstance(node, list):
            for v in node:
                walk(v, key)
        elif isinstance(node, str) and key.endswith("_zh") and node:
            out.add(node)

    data = ROOT / "src" / "mechdesign" / "data"
    for path in sorted(data.glob("*.yaml")):
        walk(yaml.safe_load(path.read_text(encoding="utf-8")))
    for path in sorted(data.glob("*.csv")):
        lines = [x for x in path.read_text(encoding="utf-8").splitlines() if not x.startswith("#")]
        for row in csv.DictReader(lines):
            out.update(v for k, v in row.items() if k and k.endswith("_zh") and v)
    return out


def main(argv: list[str]) -> int:
    if not argv:
        print(__doc__)
        return 2
    cmd, args = argv[0], argv[1:]
    if cmd == "check":
        missing, obsolete = problems()
        for line in missing:
            print("missing in zh.po:", line)
        for line in obsolete:
            print("obsolete in zh.po:", line)
        print(f"{len(missing)} missing, {len(obsolete)} obsolete")
        return 1 if missing or obsolete else 0
    if cmd == "add":
        context = None
        if "--context" in args:
            i = args.index("--context")
            context = args[i + 1]
            args = args[:i] + args[i + 2:]
        return add([[args[0], args[1]] + ([context] if context else [])])
    if cmd == "add-json":
        return add(json.loads(Path(args[0]).read_text(encoding="utf-8")))
    if cmd == "prune":
        found = extracted()
        cat = load("zh")
        for m in list(cat):
            if m.id and (m.context, m.id) not in found:
                cat.delete(m.id, context=m.context)
        save(cat, "zh")
        return 0
    if cmd == "tw":
        import opencc

        conv = opencc.OpenCC("s2twp")
        src = load("zh")
        out = Catalog(locale="zh_TW", domain="mechdesign", project="mechdesign",
                      fuzzy=False)
        for m in src:
            if m.id and m.string:
                out.add(m.id, conv.convert(m.string), context=m.context)
        save(out, "zh_TW")
        names = {t: conv.convert(t) for t in data_texts() if conv.convert(t) != t}
        (LOCALE / "zh_TW.data.json").write_text(
            json.dumps(dict(sorted(names.items())), ensure_ascii=False, indent=1) + "\n", encoding="utf-8")
        return 0
    if cmd == "union":
        with open(args[0], "rb") as fa, open(args[1], "rb") as fb:
            a, b = read_po(fa, locale="zh"), read_po(fb, locale="zh")
        clashes = 0
        for m in b:
            if not m.id:
                continue
            old = a.get(m.id, context=m.context)
            if old is None:
                a.add(m.id, m.string, context=m.context)
            elif old.string != m.string:
                print(f"clash: {m.id!r} [{m.context}]: {old.string!r} vs {m.string!r}",
                      file=sys.stderr)
                clashes += 1
        save(a, "zh")
        return 1 if clashes else 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

"""Translations live in catalogues (src/mechdesign/locale/*.po), not in the code.

- every string the code and templates mark for translation has its Chinese in zh.po, and
  zh.po has nothing that no code uses (tools/i18n.py check, with Babel's extractors);
- zh_TW.po is zh.po converted to Traditional Chinese (OpenCC s2twp), entry by entry;
- the lookup falls back variant → base catalogue → the English msgid;
- no module outside ``NOT_YET_CONVERTED`` holds a Chinese string literal (docstrings and
  pydantic ``description=`` texts, which document the code and the brief, excepted), and
  every module in that list still holds one (the list only shrinks).
"""
from __future__ import annotations

import ast
import importlib.util
import re
from pathlib import Path

import pytest

from mechdesign import i18n

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src" / "mechdesign"
CJK = re.compile(r"[\u3400-\u9fff\uff00-\uffef\u3000-\u303f]")


def _tool():
    spec = importlib.util.spec_from_file_location("i18n_tool", ROOT / "tools" / "i18n.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_every_marked_string_is_in_the_chinese_catalogue_and_none_is_obsolete():
    missing, obsolete = _tool().problems()
    assert not missing, "strings without Chinese (python tools/i18n.py add …):\n" + "\n".join(missing[:40])
    assert not obsolete, "zh.po entries no code uses (python tools/i18n.py prune):\n" + "\n".join(obsolete[:40])


def test_traditional_catalogue_is_the_conversion_of_the_simplified_one():
    opencc = pytest.importorskip("opencc")
    conv = opencc.OpenCC("s2twp")
    zh, tw = i18n.catalogue("zh"), i18n.catalogue("zh_TW")
    assert tw, "zh_TW.po is empty (python tools/i18n.py tw)"
    wrong = [(k, v, tw[k]) for k, v in zh.items() if k in tw and tw[k] != conv.convert(v)]
    assert not wrong[:5]
    assert set(tw) <= set(zh)


def test_lookup_falls_back_from_variant_to_base_to_english(monkeypatch):
    zh = {(None, "crank"): "曲柄", (None, "frame"): "机架", ("link", "frame"): "机架(杆)"}
    tw = {(None, "crank"): "曲柄(tw)"}
    monkeypatch.setattr(i18n, "catalogue", lambda name: {"zh": zh, "zh_TW": tw}[name])
    _ = i18n.tr("zh")
    assert _("crank") == "曲柄" and _("no such text") == "no such text"
    assert _.pgettext("link", "frame") == "机架(杆)" and _("frame") == "机架"
    assert i18n.tr("zh_TW")("crank") == "曲柄(tw)" and i18n.tr("zh_TW")("frame") == "机架"
    assert i18n.tr("en")("crank") == "crank"
    try:
        assert i18n.use("zh_TW") == "zh"
        assert _("crank") == "曲柄(tw)"          # the run's variant serves its base language
        assert i18n.tr("en")("crank") == "crank"
    finally:
        i18n.set_variant(None)
    assert _("crank") == "曲柄"


def test_fields_are_filled_after_translation(monkeypatch):
    zh = {(None, "crank a = {a} mm"): "曲柄 a = {a} mm"}
    monkeypatch.setattr(i18n, "catalogue", lambda name: zh if name == "zh" else {})
    assert i18n.tr("zh")("crank a = {a} mm", a="12.5") == "曲柄 a = 12.5 mm"
    assert i18n.tr("en")("crank a = {a} mm", a="12.5") == "crank a = 12.5 mm"


@pytest.mark.parametrize("given, want", [("zh", "zh"), ("EN", "en"), ("zh-tw", "zh_TW"),
                                         ("ZH_TW", "zh_TW"), ("fr", None), (None, None)])
def test_language_names_are_case_and_separator_insensitive(given, want):
    assert i18n.canonical(given) == want


def chinese_literals(path: Path) -> list[tuple[int, str]]:
    """(line, text) of the Chinese string literals in a module, docstrings and pydantic
    ``description=`` texts excepted."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skip = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                skip.add(id(body[0].value))
        if isinstance(node, ast.keyword) and node.arg == "description":
            for sub in ast.walk(node.value):
                skip.add(id(sub))
    return [(n.lineno, n.value) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in skip
            and CJK.search(n.value)]


#: Modules whose words are still written in the code, language by language (issue 22:
#: being moved into the catalogues; the core's messages become codes and numbers). The
#: list only shrinks. A module that needs Chinese characters that are not prose (a regular
#: expression of CJK punctuation, say) goes into NOT_PROSE with the reason.
NOT_YET_CONVERTED: set[str] = set()      # every module converted (session 28)


#: module → why its Chinese literals are not words to translate
NOT_PROSE: dict[str, str] = {
    "data/catalogues.py": "钢 (steel) is dropped when a material name is matched (\"45钢\" = \"45\")",
    "render/mathbreak.py": "the bounds of the CJK character ranges (ideographs, CJK "
                           "punctuation, fullwidth forms) that decide where a line may break",
    "render/docx.py": "the full-width punctuation (（【＝：，；、～) after which a '-' before a digit "
                      "is a minus sign in Word's text (minus_signs)",
    "render/docx_layout.py": "the full-width colon (：) that ends a lead-in paragraph kept with the "
                             "formula, table or list it introduces (keep_lead_ins)",
    "render/report.py": "the ideographic full stop (。) before which a citation is set "
                        "(cited: '…重新校核[7, 9]。')",
    "cli.py": "the English --help texts gloss two course terms in Chinese (机械原理课程设计, "
              "分组), as the brief's field descriptions do; its messages are in the catalogue",
}


def _modules():
    return sorted(p for p in SRC.rglob("*.py"))


def test_no_chinese_literal_outside_the_modules_not_yet_converted():
    offenders = {}
    for path in _modules():
        rel = path.relative_to(SRC).as_posix()
        if rel in NOT_YET_CONVERTED or rel in NOT_PROSE:
            continue
        found = chinese_literals(path)
        if found:
            offenders[rel] = found[:3]
    assert not offenders, ("Chinese text in the code: put it in locale/zh.po "
                           "(_ = tr(lang); _(\"English\")):\n" +
                           "\n".join(f"{k}: {v}" for k, v in offenders.items()))


#: The only core modules that may still hold Chinese: the handbook checks, converted by
#: another part of issue 22 (each leaves NOT_YET_CONVERTED when it is converted).
CORE_BEING_CONVERTED = {"core/belts.py", "core/chains.py", "core/strength.py"}


def test_the_core_returns_codes_and_numbers_never_prose():
    """Issue 22: the computational core holds no Chinese (its messages are English msgids
    with fields, translated where they are shown), but for the modules still listed."""
    listed = {m for m in NOT_YET_CONVERTED if m.startswith("core/")}
    assert listed <= CORE_BEING_CONVERTED, sorted(listed - CORE_BEING_CONVERTED)
    found = {p.relative_to(SRC).as_posix(): chinese_literals(p)[:3]
             for p in sorted((SRC / "core").glob("*.py"))}
    found = {k: v for k, v in found.items() if v and k not in listed}
    assert not found, found


def test_a_design_error_is_a_msgid_with_fields_translated_where_shown(monkeypatch):
    import pickle

    from mechdesign.core.errors import DesignError, Join, Msg, chinese_of, pgettext
    from mechdesign.core.mechanism import AssemblyError

    zh = {(None, "a crank of {a} mm is too short{why}"): "曲柄 {a} mm 太短{why}",
          (None, " (at least {n})"): "（至少 {n}）", ("separator", "; or "): "；或",
          (None, "{message} {hint}"): "{message}{hint}"}
    monkeypatch.setattr(i18n, "catalogue", lambda name: zh if name == "zh" else {})
    e = DesignError("a crank of {a} mm is too short{why}", a="12.5",
                    why=Msg(" (at least {n})", n=3))
    assert str(e) == e.en == "a crank of 12.5 mm is too short (at least 3)"
    assert e.text("zh") == e.zh == "曲柄 12.5 mm 太短（至少 3）" and e.text("en") == str(e)
    back = pickle.loads(pickle.dumps(e))
    assert type(back) is DesignError and back.text("zh") == e.text("zh") and str(back) == str(e)
    # a brief validator that quoted the English text in a plain ValueError
    assert chinese_of(f"crank_mm = 12.5: {e}") == f"crank_mm = 12.5: {e.zh}"
    assert Join(pgettext("separator", "; or "), ["a", Msg(" (at least {n})", n=1)]).text("zh") \
        == "a；或（至少 1）"
    # the two-language form of raise sites outside the core
    legacy = DesignError("no solution", "无实解")
    assert (str(legacy), legacy.text("zh"), legacy.text("zh_TW")) == ("no solution", "无实解", "无实解")
    assert DesignError("only English").text("zh") == "only English"
    # subclasses keep their attributes through pickling and hints
    err = AssemblyError("RRR1", "RRR", 12.0, 3, code="grashof", numbers={"a": 0.1})
    hinted = err.with_hint("(Brief field: x.)", "（任务书字段：x。）")
    assert str(hinted).endswith(" (Brief field: x.)") and hinted.text("zh").endswith("。）")
    back = pickle.loads(pickle.dumps(hinted))
    assert (back.group, back.code, back.count, back.numbers, str(back)) == \
        ("RRR1", "grashof", 3, {"a": 0.1}, str(hinted))


def test_the_list_of_modules_not_yet_converted_only_shrinks():
    done = sorted(rel for rel in NOT_YET_CONVERTED
                  if not (SRC / rel).exists() or not chinese_literals(SRC / rel))
    assert not done, f"converted (take them off NOT_YET_CONVERTED): {done}"


def test_adding_a_language_is_adding_its_catalogue(tmp_path, monkeypatch):
    """A de.po beside the shipped catalogues makes "de" a report language (the en report's
    structure, the words of its catalogue): nothing else to register."""
    import shutil
    from importlib import resources

    shipped = Path(str(resources.files("mechdesign.locale")))
    for po in shipped.glob("*.mo"):
        shutil.copy(po, tmp_path / po.name)
    (tmp_path / "de.po").write_text('msgid ""\nmsgstr ""\n"Content-Type: text/plain; charset=utf-8\\n"\n\n'
                                    'msgid "the cam cannot be designed"\n'
                                    'msgstr "die Kurvenscheibe ist nicht auslegbar"\n', encoding="utf-8")
    from babel.messages.mofile import write_mo
    from babel.messages.pofile import read_po

    with open(tmp_path / "de.po", "rb") as src, open(tmp_path / "de.mo", "wb") as dst:
        write_mo(dst, read_po(src))          # what tools/i18n.py does for a shipped catalogue
    monkeypatch.setattr(i18n.resources, "files", lambda pkg: tmp_path)
    i18n.catalogue.cache_clear()
    try:
        langs = i18n._discover()
        assert langs[:2] == ("zh", "en") and {"zh_TW", "de"} <= set(langs)
        assert i18n.base("de") == "en" and i18n.base("zh_TW") == "zh"
        assert i18n.tr("de")("the cam cannot be designed") == "die Kurvenscheibe ist nicht auslegbar"
        assert i18n.tr("de")("the drive cannot be designed") == "the drive cannot be designed"
    finally:
        i18n.catalogue.cache_clear()


@pytest.mark.e2e
def test_a_traditional_chinese_report_renders(tmp_path):
    """`--lang zh_TW` renders the zh report with the words of zh_TW.po: the catalogue's
    texts that the zh report shows appear converted, and the numbers are the same."""
    opencc = pytest.importorskip("opencc")
    import json
    import subprocess
    import sys

    brief = ROOT / "designs" / "cam_7_1.yaml"
    out = {}
    for lang in ("zh", "zh_TW"):
        folder = tmp_path / lang
        run = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "--lang", lang,
                              "--format", "md", "-o", str(folder)], capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        out[lang] = ((folder / "report.md").read_text(encoding="utf-8"),
                     json.loads((folder / "results.json").read_text(encoding="utf-8")))
    (zh_md, zh_res), (tw_md, tw_res) = out["zh"], out["zh_TW"]
    conv = opencc.OpenCC("s2twp")
    shown = [s for s in i18n.catalogue("zh").values()
             if len(s) >= 4 and "{" not in s and "%" not in s and s in zh_md and conv.convert(s) != s]
    assert len(shown) >= 20
    converted = [s for s in shown if conv.convert(s) in tw_md]
    assert len(converted) >= 0.9 * len(shown), [s for s in shown if s not in converted][:10]
    assert tw_md != zh_md

    def numbers(doc):
        if isinstance(doc, dict):
            return {k: numbers(v) for k, v in doc.items() if not isinstance(v, str)}
        if isinstance(doc, list):
            return [numbers(v) for v in doc if not isinstance(v, str)]
        return doc
    assert numbers(tw_res) == numbers(zh_res)


def test_the_compiled_catalogues_are_current():
    """The program reads locale/<lang>.mo (standard-library gettext, no Babel at run time);
    each must be its .po compiled (python tools/i18n.py writes both)."""
    import gettext
    from io import BytesIO

    def messages(mo: bytes) -> dict:
        """The compiled catalogue's messages (the header without Babel's version line, which
        differs between Babel releases while the translations are the same)."""
        catalog = dict(gettext.GNUTranslations(BytesIO(mo))._catalog)
        catalog[""] = "".join(line for line in catalog.get("", "").splitlines(keepends=True)
                              if not line.startswith("Generated-By:"))
        return catalog

    tool = _tool()
    for name in ("zh", "zh_TW"):
        path = SRC / "locale" / f"{name}.mo"
        shipped = path.read_bytes()
        try:
            assert messages(tool.compile_mo(name)) == messages(shipped), \
                f"{name}.mo is stale: python tools/i18n.py check"
        finally:
            path.write_bytes(shipped)


@pytest.mark.parametrize("given, want", [("zh-tw", "zh_TW"), ("zh-TW", "zh_TW"), ("ZH_TW", "zh_TW"),
                                         ("zh_tw", "zh_TW"), ("en", "en"), ("EN", "en"), ("Zh", "zh")])
def test_lang_option_is_case_and_separator_insensitive(given, want):
    """`--lang zh-tw` / `zh-TW` / `EN` are accepted as zh_TW / en by every command (issue 22);
    an unknown language is refused with exit 2 and the allowed ones listed."""
    from typer.testing import CliRunner

    from mechdesign.cli import _parse_lang, app

    assert _parse_lang(given).value == want
    brief = str(ROOT / "designs" / "cam_7_1.yaml")
    assert CliRunner().invoke(app, ["check", brief, "--lang", given]).exit_code == 0
    bad = CliRunner().invoke(app, ["check", brief, "--lang", given + "x"])
    assert bad.exit_code == 2 and "zh_TW" in bad.output


def test_batch_index_is_in_the_language_the_briefs_share(tmp_path):
    """A batch's index.md and answer table follow --lang, else the report.language every
    brief gives (English briefs: an English index), else Chinese (issue 22 point 3)."""
    from types import SimpleNamespace

    from mechdesign.cli import Lang, _index_lang

    def brief(name, lang):
        path = tmp_path / f"{name}.yaml"
        path.write_text(f"machine: shaper\nreport:\n  language: {lang}\n", encoding="utf-8")
        return SimpleNamespace(brief=path)

    english = [brief("a", "en"), brief("b", "en")]
    assert _index_lang(None, english) == "en"
    assert _index_lang(None, english + [brief("c", "zh")]) == "zh"
    assert _index_lang(Lang("zh"), english) == "zh"
    assert _index_lang(None, [brief("d", "zh_TW")]) == "zh" and i18n.variant() == "zh_TW"
    i18n.set_variant(None)


def test_traditional_data_names_are_the_conversion_of_the_data_tables():
    """locale/zh_TW.data.json holds every Chinese text of the data tables (materials,
    transmissions, load classes: the ``*_zh`` fields) that the zh_TW conversion changes,
    converted the way zh_TW.po is (OpenCC s2twp, python tools/i18n.py tw)."""
    opencc = pytest.importorskip("opencc")
    conv = opencc.OpenCC("s2twp")
    texts = _tool().data_texts()
    assert {"45 钢调质", "V带传动", "开式直齿圆柱齿轮传动"} <= texts
    i18n.data_names.cache_clear()
    want = {t: conv.convert(t) for t in texts if conv.convert(t) != t}
    assert i18n.data_names("zh_TW") == want
    assert i18n.data_names("zh") == {}


def test_data_text_converts_in_a_traditional_run_only(monkeypatch):
    assert i18n.data_text("45 钢调质", "zh") == "45 钢调质"
    assert i18n.data_text("45 钢调质", "zh_TW") == "45 鋼調質"
    assert i18n.data_text("not in the tables", "zh_TW") == "not in the tables"
    monkeypatch.setattr(i18n, "_variant", "zh_TW")        # a zh_TW run asks for "zh"
    assert i18n.data_text("45 钢调质", "zh") == "45 鋼調質"
    assert i18n.data_text("45 钢调质", "en") == "45 钢调质"


@pytest.mark.e2e
def test_a_traditional_report_writes_the_data_tables_names_converted(tmp_path):
    """The shaper's drive names its stages and materials from the data tables: in the zh_TW
    report none of them is left in Simplified characters, each is in its converted form."""
    import subprocess
    import sys

    md = {}
    for lang in ("zh", "zh_TW"):
        run = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(ROOT / "designs" / "shaper.yaml"),
                              "--lang", lang, "--format", "md", "-o", str(tmp_path / lang)],
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        md[lang] = (tmp_path / lang / "report.md").read_text(encoding="utf-8")
    names = i18n.data_names("zh_TW")
    shown = [s for s in names if s in md["zh"]]
    assert len(shown) >= 4, shown                  # stages and materials of the shaper's drive
    assert not [s for s in shown if s in md["zh_TW"]]
    assert all(names[s] in md["zh_TW"] for s in shown), [names[s] for s in shown if names[s] not in md["zh_TW"]]

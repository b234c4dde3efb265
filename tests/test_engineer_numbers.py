"""Numbers as an engineer writes them, in every example report (issue 19 point 5).

render/fmt.py states the rule; this scans the Markdown of every example brief in both
languages (formulas and tables included, the program listing left out) for the faults a
page review found: five or more decimals with five or more significant digits (``K = 2.000000``, ``cos δ' = 0.683012``),
E-notation (``4.8e+04``), a negative zero, numbers of seven or more digits (a bearing life
of ``40 680 894 h``, a press load of ``1 000 000.0 N``: a power of ten or a larger unit), and
a length or angle in running text or a formula written to 0.0001 (``h = 40.0000 mm``: the
rule is 0.01 mm and 0.01°; the crank-rocker's worked example keeps the four decimals of the
paper it reproduces, and tables keep the decimals their column states).

Outside the tables also: a torque, force, power, energy or moment of inertia written with more
digits than both 4 significant digits and a resolution of 0.1 allow (``12 738.160 N·m``,
``636.620 N·m``, ``3333.33 W``, ``3.8033 kW``, ``190.322 J``; ``12 738.2 N·m`` to 0.1 N·m and
``12 740 N·m`` are right). The furnace pusher's and the die-cutter's given-dimensions path
(``dimensions:`` instead of H and K), which no example takes, is scanned on a brief variant,
and the finding messages (``finding(...)`` msgids) on their format fields.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

from tests.test_report_prose import EXAMPLES, _markdown

ROOT = Path(__file__).resolve().parents[1]

FAULTS = {
    # five or more decimals and five or more significant digits (0.06233 kW is 4 digits)
    "five or more decimals": re.compile(r"(?<![\d.])(?:-?[1-9]\d*\.\d{5,}|0\.0*[1-9]\d{4,})"),
    "E-notation": re.compile(r"\d[eE][-+]?\d"),
    "negative zero": re.compile(r"(?<![\w.])[-−]0(\.0+)?(?![.\d])"),
    "seven or more digits": re.compile(r"(?<![\d\u202f.])(\d{7,}|\d{1,3}(?:\u202f\d{3}){2,})(?![\d\u202f])"),
}
# a length or angle to 0.0001 outside a table (``40.0000 mm``, ``20.0000°``, ``\ \text{mm}``)
LENGTH_4 = re.compile(r"\d\.\d{4}(?:\\ |\s)*(?:\\text\{\s*)?(?:mm\b|°)")
KEEPS_SOURCE_DECIMALS = {"crank_rocker"}
# a torque, force, power, energy or inertia (outside a table) with five or more significant
# digits and two or more decimals: more than 4 significant digits and finer than 0.1
_NUMBER = r"(?<![\d.\u202f])-?(?:\d{1,3}(?:\u202f\d{3})+|\d+)\.\d+(?!\d)"
DECADES = re.compile(rf"({_NUMBER})(?:\$|\s|\\ |\\text\{{|\\,)*(?:N·m|kN·m|W\b|kW\b|J\b|kJ\b|kg·m|N\b|kN\b)")


def _too_many_digits(number: str) -> bool:
    head, _, tail = number.replace("\u202f", "").lstrip("-").partition(".")
    return len((head + tail).lstrip("0")) >= 5 and len(tail) >= 2


def faults(md: str, name: str = "") -> list[tuple[str, str]]:
    """(kind, line) for every fault in a report's Markdown (code blocks left out)."""
    md = re.sub(r"^```.*?^```", "", md, flags=re.S | re.M)
    out = []
    for line in md.splitlines():
        for kind, pattern in FAULTS.items():
            if pattern.search(line):
                out.append((kind, line.strip()[:140]))
        if not line.startswith("|") and name not in KEEPS_SOURCE_DECIMALS and LENGTH_4.search(line):
            out.append(("length or angle to 0.0001", line.strip()[:140]))
        if not line.startswith("|") and any(_too_many_digits(m.group(1)) for m in DECADES.finditer(line)):
            out.append(("torque, power or energy beyond 4 digits", line.strip()[:140]))
    return out


def test_the_scan_finds_the_reviewed_faults():
    """The faults of the page review, as the old reports printed them, are found."""
    old = ["$$ K = \\frac{240.0000}{120.0000} = 2.000000 $$",
           "| R1 | D | 6 | 90.0 | 1\u202f000\u202f000.0 | 0.0 | 46.0 – 50.0 mm |",
           "| Bearing 30204 life | 40\u202f680\u202f894 | 48\u202f000 | h | PASS |",
           "$$ L_{10h} = 40680894\\ \\text{h} \\ge L_h' = 48000\\ \\text{h} $$",
           "Lowest position $y_{min}$ = 20.0000 mm, highest",
           "$$ h = \\sqrt{60.0^2} = 40.0000\\ \\text{mm} $$",
           "mean 4.8e+04 h", "M_b = -0.000",
           # a torque, a power, an energy and an inertia in running text and formulas
           "$M_b$ ranges from -84.696 to 12\u202f738.160 N·m, mean 636.620 N·m; the mean power",
           "design torque $T_1 = 4211.515$ N·m, face width factor",
           "$$ P = \\bar M_b\\,\\omega = 636.620 \\times 5.2360 = 3333.33\\ \\text{W} $$",
           "$$ P_d = \\frac{P_w}{\\eta} = \\frac{3.3333}{0.8764} = 3.8033\\ \\text{kW} $$",
           "the largest energy swing is $\\Delta W_{max}$ = 190.322 J (ΔE lowest",
           "$$ J_F = \\frac{900 \\times 190.322}{\\pi^2} = 96.4182\\ \\text{kg·m}^2 $$",
           # the given-dimensions path's formulas
           "$$ \\psi = 18.446977° - 7.444353° = 11.002624° $$",
           "$$ K = \\frac{180° + \\theta}{180° - \\theta} = 1.249567 $$"]
    assert len({line for _, line in faults("\n".join(old), "cam_7_1")}) == len(old)
    ok = ["| 1 | 0.00 | 0.0000 | 5.7162 |", "$$ L_{10h} = 4.068\\times10^{7}\\ \\text{h} $$",
          "life 4.068 × 10⁷ h", "12\u202f698.4 N·m", "P = 0.06233 kW", "```\nx = 1e-12\n```", "h = 40.00 mm",
          "peaks at 12\u202f738.2 N·m, 20.01 times its mean 636.6 N·m", "$T_1 = 4212$ N·m",
          "$$ P = 636.6 \\times 5.2360 = 3333\\ \\text{W} $$", "$R_{AH} = -24794.2$ N",
          "| torque | 636.620 | N·m |", "$$ \\psi = 18.45° - 7.44° = 11.00° $$"]
    assert not faults("\n".join(ok), "cam_7_1")


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_numbers_as_an_engineer_writes_them(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad = faults(md, name)
    assert not bad, "\n".join(map(str, bad[:12]))


def _given_dimensions_briefs(tmp_path: Path) -> dict[str, Path]:
    """The furnace pusher and the die-cutter with their crank-rockers given by round
    dimensions (as a student's given data would be) instead of H and K."""
    out = {}
    for name, section, drop, dims in (
            ("furnace_pusher", "pusher", ("stroke_H_mm", "time_ratio_K", "rocker_ratio_DB_DC", "frame_O1D_mm"),
             {"crank_O1A_mm": 51, "coupler_AB_mm": 131, "rocker_DB_mm": 575, "frame_O1D_mm": 541}),
            ("die_cutter", "press", ("stroke_H_mm", "time_ratio_K", "frame_O1C_mm"),
             {"crank_O1A_mm": 57, "coupler_AB_mm": 158, "frame_O1C_mm": 243})):
        brief = yaml.safe_load((ROOT / "designs" / f"{name}.yaml").read_text(encoding="utf-8"))
        brief.pop("groups", None)
        for key in drop:
            brief[section].pop(key, None)
        brief[section]["dimensions"] = dims
        out[name] = tmp_path / f"{name}_dims.yaml"
        out[name].write_text(yaml.safe_dump(brief, allow_unicode=True), encoding="utf-8")
    return out


def test_given_dimensions_path(tmp_path):
    """The given-dimensions path (no example takes it) writes its derived H, K, θ and ψ as
    the rule says, in both languages (it printed ``θ = |111.371754° − 91.402537°|`` and
    ``K = 1.249567``)."""
    from typer.testing import CliRunner

    from mechdesign.cli import app

    runner = CliRunner()
    for name, brief in _given_dimensions_briefs(tmp_path).items():
        for lang in ("zh", "en"):
            out = tmp_path / f"{name}.{lang}"
            result = runner.invoke(app, ["run", str(brief), "--out", str(out), "--format", "md",
                                         "--lang", lang])
            assert result.exit_code == 0, result.output
            md = (out / "report.md").read_text(encoding="utf-8")
            assert "(derived)" in md or "导出" in md, "the variant must take the given-dimensions path"
            bad = faults(md, name)
            assert not bad, f"{name} {lang}:\n" + "\n".join(map(str, bad[:12]))


def test_finding_messages():
    """No finding message formats a number with more digits than the rule allows: a length
    to 0.01 mm, an angle to 0.01°, K to 4 decimals, a speed to 0.01 rpm, ratios to 4
    significant digits (the furnace pusher's ``{H:.4f} mm and K = {K:.5f}``, the lock-beam's
    ``{n:.3f} rpm``), never ``{x!r}`` of a number."""
    from mechdesign.i18n import N_  # noqa: F401  (the catalogue holds every msgid)

    po = (ROOT / "src" / "mechdesign" / "locale" / "zh.po").read_text(encoding="utf-8")
    msgids = re.findall(r'^msgid "(.*)"$', po, flags=re.M)
    # three decimals kept: shift coefficients, a tiny cut, contact and stage ratios to 0.001 as
    # the drive tables write them, the worm's d1/a chart coordinate, a motor power in kW; and
    # values compared with a limit they may miss by less than 0.01 (γmin of given lengths,
    # the lock-beam pin's lift against its stroke)
    fine = {"x_min", "cut", "eps", "i", "x", "power_kw", "lift", "stroke", "g", "d1", "d2"}
    bad = []
    for msgid in msgids:
        for name, spec in re.findall(r"\{(\w+):[+]?\.(\d+)f\}", msgid):
            if int(spec) >= 5 or (int(spec) >= 3 and name not in fine and name != "K") \
                    or (name == "K" and int(spec) > 4):
                bad.append(msgid[:120])
    assert not bad, "\n".join(bad)

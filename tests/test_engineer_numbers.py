"""Numbers as an engineer writes them, in every example report (issue 19 point 5).

render/fmt.py states the rule; this scans the Markdown of every example brief in both
languages (formulas and tables included, the program listing left out) for the faults a
page review found: five or more decimals with five or more significant digits (``K = 2.000000``, ``cos δ' = 0.683012``),
E-notation (``4.8e+04``), a negative zero, numbers of seven or more digits (a bearing life
of ``40 680 894 h``, a press load of ``1 000 000.0 N``: a power of ten or a larger unit), and
a length or angle in running text or a formula written to 0.0001 (``h = 40.0000 mm``: the
rule is 0.01 mm and 0.01°; the crank-rocker's worked example too — where it shows the
paper's printed digits it says so, "the paper prints 16.2227 mm" — and tables keep the
decimals their column states).

Outside the tables also: a torque, force, power, energy or moment of inertia written with more
digits than both 4 significant digits and a resolution of 0.1 allow (``12 738.160 N·m``,
``636.620 N·m``, ``3333.33 W``, ``3.8033 kW``, ``190.322 J``; ``12 738.2 N·m`` to 0.1 N·m and
``12 740 N·m`` are right). The furnace pusher's and the die-cutter's given-dimensions path
(``dimensions:`` instead of H and K), which no example takes, is scanned on a brief variant,
and the finding messages (``finding(...)`` msgids) on their format fields.

Outside the tables also (the second page review): any number with five or more significant
digits and three or more decimals — no quantity of the rule has both (``n_w = 50.000 rpm``,
``ω = 5.2360 rad/s``, ``K = 1.2000``, ``a = 57.041 mm``, ``12.290 m/s²``, ``i = 28.800``,
``Φ = 2.0944 rad``); a length or angle to 0.001 (``s_0 = 48.539 mm``, ``\\sin 8.182°``,
``φ_v = 2.087°``); the time ratio K to four decimals (``K = 1.0505``: the textbook writes
K = 1.4, the rule K to 0.001); a percentage finer than 0.1 % (``2.63 %``). And a value of
five or more integer digits keeps all of them: the die-cutter's peak torque 12 738.2 N·m was
also written ``12 740 N·m`` (4 significant digits), which read as another value.
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
# a torque, force, power, energy or inertia (outside a table) with five or more significant
# digits and two or more decimals: more than 4 significant digits and finer than 0.1
_NUMBER = r"(?<![\d.\u202f])-?(?:\d{1,3}(?:\u202f\d{3})+|\d+)\.\d+(?!\d)"
DECADES = re.compile(rf"({_NUMBER})(?:\$|\s|\\ |\\text\{{|\\,)*(?:N·m|kN·m|W\b|kW\b|J\b|kJ\b|kg·m|N\b|kN\b)")


KNOWN_LOADS = ("Known loads: ", "作用在杆组上的已知力：", "作用在曲柄上的已知力：")

# five or more significant digits written with three or more decimals (``n_w = 50.000 rpm``,
# ``ω = 5.2360 rad/s``, ``K = 1.2000``, ``57.041 mm``, ``12.290 m/s²``, ``i = 28.800``): no
# quantity of the rule has both (lengths and angles 0.01, speeds 0.01 rpm, K 0.001, the rest
# 4 significant digits)
FIVE_SIG_3DEC = re.compile(r"(?<![\d.\u202f])(?:[1-9]\d*\.\d{3,}|0\.0*[1-9]\d{4,})(?!\d)")
# a length or angle to 0.001 outside a table (``s_0 = 48.539 mm``, ``\\sin 8.182°``); a length
# below 0.1 mm (a deflection limit of 0.025 mm, a cam's stand-off of 0.028 mm) has two
# significant digits
LENGTH_3 = re.compile(r"(?<![\d.])(?:[1-9]\d*\.\d{3}|0\.[1-9]\d{2})(?!\d)(?:\\ |\s)*(?:\\text\{\s*)?"
                      r"(?:mm\b|°)")
# numbers a report quotes from its source as the source writes them, said to be the source's
# (the lock-beam seed's lift, beside this design's h to 0.01 mm)
QUOTED = {"lockbeam": ("the original report prints 14.904 mm", "原报告印作 14.904 mm")}
# the crank-rocker's compared designs as the paper prints them (the table rounds to 0.01 mm)
QUOTED_PATTERN = {"crank_rocker": re.compile(r"(?:the paper prints|论文印作) [^)）]*[)）]")}
# numbers that carry one more digit than the rule so that a chain printed from them gives its
# printed result (session 39, text39; tests/test_every_chain.py): the terms of a half sum
# (a ± b)/2 printed to 0.001 mm where 0.01 mm would end the half exactly in half a unit
# (numbers.half_sum_decimals: crank_rocker's AC₁, AC₂; furnace_pusher's sagitta f, halved
# in the guide's offset), and the slotter's M_b in its moment equation with the digits its
# P_b equation divides (M_b = −44.343 N·m, P_b = M_b/l printed −1069)
EXEMPT = {
    "crank_rocker": (r"\\overline\{AC_[12]\}\$ = \d+\.\d{3} mm",),
    "furnace_pusher": (r"= \d+\.\d{3}\\ \\text\{mm\} \$\$(?=\n(?:.*\n){0,3}.*\\frac\{f\}\{2\})",
                       r"f = l_\{DC\}.*?= \d+\.\d{3}\\ \\text\{mm\}"),
    "slotter": (r"M_b = -?\d+\.\d{3}\\ \\text\{N·m\}",),
}
# the time-ratio K to four decimals (the textbook writes K = 1.4, K = 1.25: 3 decimals)
K_4 = re.compile(r"(?<![\w\\{])K\s*=\s*\d+\.\d{4,}")
# a percentage finer than 0.1 % or than two significant digits (``0.542%``, ``33.21 %``)
PERCENT = re.compile(r"(?<![\d.])(?:[1-9]\d*\.\d{2,}|0\.\d{3,})(?:\\ |\s)*\\?%")


def _five_sig_3dec(number: str) -> bool:
    head, _, tail = number.partition(".")
    return len((head + tail).lstrip("0")) >= 5 and len(tail) >= 3


def _too_many_digits(number: str) -> bool:
    head, _, tail = number.replace("\u202f", "").lstrip("-").partition(".")
    return len((head + tail).lstrip("0")) >= 5 and len(tail) >= 2


def faults(md: str, name: str = "") -> list[tuple[str, str]]:
    """(kind, line) for every fault in a report's Markdown (code blocks left out)."""
    md = re.sub(r"^```.*?^```", "", md, flags=re.S | re.M)
    for quoted in QUOTED.get(name, ()):
        md = md.replace(quoted, "")
    if name in QUOTED_PATTERN:
        md = QUOTED_PATTERN[name].sub("", md)
    for pattern in EXEMPT.get(name, ()):
        md = re.sub(pattern, "", md)
    out = []
    for line in md.splitlines():
        # a displayed chain's result is written by the rule; its factors may carry the digits
        # the result was computed from, so that the printed factors give the printed result
        # (review35: "6.404 × 14.12² = 1276.5", "320/(2 sin 8.18°) = 1124.27"; an inline
        # chain too: "$T = 20.009 \times 640.06 = 12807$ N·m", its result 12807; a long
        # display whose numbers end it, its result on the next line, has no result on this
        # one; tests/test_displayed_arithmetic.py and tests/test_every_chain.py check the chains)
        if line.lstrip().startswith("$$"):
            result = line.rsplit("=", 1)[-1]
            head = re.sub(r"\\times\s*10\^\{?-?\d+\}?", "", result.split("\\ ")[0])
            if re.search(r"\\times|\\frac|\^", head.split("\\le")[0].split("\\ge")[0]):
                result = ""
        else:
            result = re.sub(r"\$[^$]*=([^$=]*)\$", r"$\1$", line)
        for kind, pattern in FAULTS.items():
            if pattern.search(result if kind == "five or more decimals" else line):
                out.append((kind, line.strip()[:140]))
        if not line.startswith("|") and LENGTH_4.search(
                line.rsplit("=", 1)[-1] if line.lstrip().startswith("$$") else line):
            out.append(("length or angle to 0.0001", line.strip()[:140]))
        # a group's known loads print with the digits its moment equations need (the printed
        # factors give the printed sum, tests/test_displayed_arithmetic.py; one value of a
        # force in its section): a weight m g = 25 × 9.81 = 245.25 N as the equation uses it
        known = line.startswith(KNOWN_LOADS)
        if not line.startswith("|") and not known and any(
                _too_many_digits(m.group(1)) for m in DECADES.finditer(line)):
            out.append(("torque, power or energy beyond 4 digits", line.strip()[:140]))
        if line.startswith("|"):
            continue
        if any(_five_sig_3dec(m.group(0)) for m in FIVE_SIG_3DEC.finditer(result)):
            out.append(("five significant digits and three decimals", line.strip()[:140]))
        if LENGTH_3.search(result):
            out.append(("length or angle to 0.001", line.strip()[:140]))
        if K_4.search(line):
            out.append(("K to four decimals", line.strip()[:140]))
        if PERCENT.search(line):
            out.append(("percentage beyond 0.1 % or 2 digits", line.strip()[:140]))
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
           "$$ K = \\frac{180° + \\theta}{180° - \\theta} = 1.249567 $$",
           # the second review: speeds, ω, K, lengths of the synthesis formulas, accelerations,
           # ratios, radians, percentages (as the reports of main a469fe1 printed them)
           "$$ i = \\frac{n_m}{n_w} = \\frac{1440}{50.000} = 28.800 $$",
           "The crank drives at n = 50.00 rpm clockwise (ω = 5.2360 rad/s); the other links",
           "stroke 50.00 mm; working stroke 196.36°, return 163.64°, time ratio K = 1.2000 (θ = 16.36°)",
           "$$ a = \\frac{AC_2 - AC_1}{2} = 57.041\\ \\text{mm},\\quad b = 157.966\\ \\text{mm} $$",
           "Largest ram speed 1.563 m/s, largest ram acceleration 12.290 m/s².",
           "$$ u = \\frac{\\delta}{\\Phi},\\quad \\Phi = 120.0° = 2.0944\\ \\text{rad} $$",
           "$$ s_0 = \\sqrt{r_0^2 - e^2} = \\sqrt{50.00^2 - 12.00^2} = 48.539\\ \\text{mm} $$",
           # (a factor's digits are no fault since session 35: "2 sin 25.714°" gives the
           # printed 138.29 mm, "2 sin 25.71°" 138.30; the result is written by the rule)
           "$$ \\theta = \\angle C'AC'' = 4.431°,\\quad K = \\frac{180° + \\theta}{180° - \\theta} = 1.0505 $$",
           "Simulation: stroke 250.00 mm, K = 2.0000, as the closed forms",
           "$$ \\Delta n = \\frac{n_w' - n_w}{n_w} = \\frac{61.58 - 60.00}{60.00} = 2.63\\% $$"]
    assert len({line for _, line in faults("\n".join(old), "cam_7_1")}) == len(old)
    ok = ["| 1 | 0.00 | 0.0000 | 5.7162 |", "$$ L_{10h} = 4.068\\times10^{7}\\ \\text{h} $$",
          "life 4.068 × 10⁷ h", "12\u202f698.4 N·m", "P = 0.06233 kW", "```\nx = 1e-12\n```", "h = 40.00 mm",
          "peaks at 12\u202f738.2 N·m, 20.01 times its mean 636.6 N·m", "$T_1 = 4212$ N·m",
          # ω was 5.2360 here until the second review (ω to 4 significant digits now)
          "$$ P = 636.6 \\times 5.236 = 3333\\ \\text{W} $$", "$R_{AH} = -24794.2$ N",
          "| torque | 636.620 | N·m |", "$$ \\psi = 18.45° - 7.44° = 11.00° $$",
          "$$ i = \\frac{1440}{50.00} = 28.80 $$", "(ω = 5.236 rad/s)", "K = 1.200 (θ = 16.36°)",
          "$$ a = 57.04\\ \\text{mm} $$", "acceleration 12.29 m/s²", "\\Phi = 120.0° = 2.094\\ \\text{rad}",
          "12\u202f738 N·m", "$$ \\Delta n = 0.54\\% $$", "efficiency 0.8764, 88.6%",
          "| 1 | 5.2360 | 1.2000 | 48.539 |",
          # an inline chain's factors carry the digits its printed result was computed from
          "the strength checks use $T = 20.009 \\times 640.06 = 12807$ N·m (peak/mean)"]
    assert not faults("\n".join(ok), "cam_7_1")


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_numbers_as_an_engineer_writes_them(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad = faults(md, name)
    assert not bad, "\n".join(map(str, bad[:12]))


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_die_cutter_peak_torque_reads_as_one_value(example_results, lang):
    """The die-cutter's peak balancing torque (the exact maximum between the samples) is
    written wherever it appears — the range of M_b, the peak sentence, the summary — with
    the same integer digits: 12 738 N·m or 12 738.2 N·m, never 12 740 N·m (4 significant
    digits replaced the units digit by a zero, and the page read two different peaks)."""
    peak = example_results("die_cutter")["press_forces"].peak_torque
    assert peak >= 1e4, "the die-cutter's peak torque has five integer digits"
    md, _ = _markdown(example_results, "die_cutter", lang)
    written = [float(m.replace("\u202f", "")) for m in
               re.findall(r"(?<![\d.\u202f])\d{1,3}\u202f?\d{3}(?:\.\d+)?(?![\d\u202f])", md)]
    near = [x for x in written if abs(x - peak) < 5.0]          # the peak, however rounded
    assert near, "the report writes its peak torque"
    assert all(round(x) == round(peak) for x in near), (peak, near)


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_lockbeam_lift_is_one_value(example_results, lang):
    """The lock-beam's lift h where the cam touches the input rocker is one quantity: the
    text and the swing formula write it with the same value, by the rule (0.01 mm), computed
    as the arm times the swing; the formula's 14.904 (the digits that give its Δα) is
    followed by the sentence that says it carries more digits (page review 47: the text's
    quotation "the original report prints 14.904 mm" read as if that value were not used)."""
    r = example_results("lockbeam")
    h = r["bending_cam"].params.follower.arm_length * r["bending"].input_swing * 1e3
    md, _ = _markdown(example_results, "lockbeam", lang)
    start = md.index("## " + ("Swing of the input rocker" if lang == "en" else "输入摆杆的摆角"))
    section = md[start:md.index("\n## ", start + 3)]
    # the swing formula's h may carry the digits its printed Δα = h/L was computed from
    # (tests/test_displayed_arithmetic.py); rounded by the rule it is the text's value
    values = set(re.findall(r"h = (\d+\.\d+)", section)) | {
        f"{float(x):.2f}" for x in re.findall(r"\\frac\{h\}\{L\} = \\frac\{(\d+\.\d+)\}", section)}
    assert values == {f"{h:.2f}"}, values
    assert section.replace("\\frac{14.904}", "").count("14.904") == 0
    said = "Here $h$ carries more digits." if lang == "en" else "式中 $h$ 比正文多取有效数字。"
    assert said in section[section.index("\\frac{14.904}"):]


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_crank_rocker_prints_the_papers_digits_only_as_the_papers(example_results, lang):
    """The crank-rocker's worked example follows the rule (0.01 mm); the paper's computer
    result, which the brief gives with the paper's four decimals, is written with those
    digits only where the report says that the paper prints them."""
    brief = yaml.safe_load((ROOT / "designs" / "crank_rocker.yaml").read_text(encoding="utf-8"))
    printed = [f"{d[k]:g}" for d in brief["compare"] for k in ("crank_mm", "coupler_mm", "frame_mm")
               if len(f"{d[k]:g}".partition(".")[2]) > 2]
    assert printed, "the example compares with a design printed to more than 0.01 mm"
    md, _ = _markdown(example_results, "crank_rocker", lang)
    said = "".join(QUOTED_PATTERN["crank_rocker"].findall(md))
    for number in printed:
        assert number in said, number
        assert md.count(number) == said.count(number), number
    # the table rounds them by the rule
    assert f"| {float(printed[0]):.2f} |" in md


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

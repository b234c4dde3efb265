"""The graphical method's force analysis announces moment equations only over moment
equations (page review 46: the shaper's group 5–6 at positions 4 and 10 read "Moment
equations (arms measured on the drawing …):" and then no equation, only "No known force on
link 5 has a moment about F: F_R45^t = 0"; the ram's reaction follows from the polygon)."""
from __future__ import annotations

import pytest

from mechdesign.i18n import tr
from test_handin import LANGS
from test_review46 import GRAPHICAL


def _groups(md: str) -> list[tuple[str, str]]:
    """(heading, text) of every group's (and crank's) part of the force analysis."""
    out, head, body = [], None, []
    for line in md.splitlines():
        if line.startswith("#"):
            if head is not None:
                out.append((head, "\n".join(body)))
            head, body = (line, []) if line.startswith("#### ") else (None, [])
        elif head is not None:
            body.append(line)
    if head is not None:
        out.append((head, "\n".join(body)))
    return out


@pytest.mark.parametrize("lang", LANGS)
# (the crank-rocker's and the lockbeam feed's graphical chapters are kinematic only)
@pytest.mark.parametrize("name", [g for g in GRAPHICAL if g not in ("crank_rocker", "lockbeam")])
def test_moment_equations_are_announced_only_over_moment_equations(handin_reports, name, lang):
    md, _ = handin_reports(name, lang)
    lead = tr(lang)(" Moment equations (arms measured on the drawing in mm; counter-clockwise "
                    "positive; a negative result acts against the direction assumed):").strip()
    lead_kn = tr(lang)(" Moment equations (arms measured on the drawing in mm, forces in N; "
                       "counter-clockwise positive; a negative result acts against the direction "
                       "assumed):").strip()
    groups = [(h, t) for h, t in _groups(md) if "\\Sigma M" in t or lead in t or lead_kn in t
              or "^{t} = 0" in t]
    assert groups, "no force analysis found"
    for head, text in groups:
        announced = lead in text or lead_kn in text
        equations = [ln for ln in text.splitlines() if ln.startswith("$$") and "\\Sigma M" in ln]
        assert announced == bool(equations), (head, announced, equations[:1])
    if name == "shaper":
        # the ram's group: link 5 has no known force with a moment about F at either position
        bare = [h for h, t in groups if "^{t} = 0" in t and lead not in t]
        assert len(bare) == 2

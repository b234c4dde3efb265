"""Closed-form rules that several machines' briefs share, in a module without models: a
brief that applies them does not build another machine's brief models (importing
``machines.crank_rocker.brief`` for these two functions cost the die-cutter's and the
furnace pusher's `check` ~20 ms of pydantic model building)."""
from __future__ import annotations

import math

from ..i18n import N_
from .common import Msg, Problems


def crank_rocker_problems(out: Problems, loc: tuple, a: float, b: float, c: float, d: float,
                          names: tuple[str, str, str, str], gamma_allowed_deg: float | None = None,
                          gamma_field: str = "", locs: dict | None = None) -> None:
    """Closed-form checks (plain math, no engine) of given four-bar lengths a (crank),
    b (coupler), c (rocker), d (frame): Grashof's crank-rocker condition (the crank the
    shortest link, shortest + longest < the other two) and, when ``gamma_allowed_deg`` is
    given, γ_min = min(δ', 180° − δ'') ≥ [γ]. Each problem at the field that breaks it
    (``loc`` + the field name, or ``locs[name]`` when a field lies elsewhere in the
    section); ``names`` are the four fields."""
    lengths = {names[0]: a, names[1]: b, names[2]: c, names[3]: d}
    at = {n: (locs or {}).get(n, loc + (n,)) for n in names}
    ordered = sorted(lengths.values())
    s, p, q, l_ = ordered
    sums = Msg(N_("shortest + longest = {s:g} + {l:g} = {sl:g} mm, the other two {p:g} + {q:g} "
                  "= {pq:g} mm"), s=s, l=l_, sl=s + l_, p=p, q=q, pq=p + q)
    if not s + l_ < p + q:
        longest = max(lengths, key=lengths.get)
        out.add(at[longest], lengths[longest],
                N_("{field} = {value:g}: these lengths are not a crank-rocker (Grashof: "
                   "{sums}; a crank needs shortest + longest < the other two)"),
                field=longest, value=lengths[longest], sums=sums)
        return
    if not a <= min(b, c, d):
        out.add(at[names[0]], a,
                N_("{field} = {value:g}: the crank must be the shortest link for a crank-rocker "
                   "(the shortest is {s:g} mm; with another link shortest it is a double-crank, "
                   "double-rocker or a rocker that turns)"), field=names[0], value=a, s=s)
        return
    if gamma_allowed_deg is None:
        return

    def angle(x, y, z):       # angle opposite z [°]
        return math.degrees(math.acos(max(-1.0, min(1.0, (x * x + y * y - z * z) / (2 * x * y)))))
    d1, d2 = angle(b, c, d - a), angle(b, c, d + a)
    g = min(d1, 180.0 - d2, 180.0 - d1, d2)
    if g < gamma_allowed_deg:
        out.add(loc + (gamma_field or names[1],), gamma_allowed_deg,
                N_("{field}: the given lengths have the minimum transmission angle "
                   "γmin = {g:.3f}° < the allowed {allowed:g}° (δ' = {d1:.3f}°, δ'' = "
                   "{d2:.3f}° with the crank along the frame); change the lengths or the allowed value"),
                field=gamma_field or names[1], g=g, allowed=gamma_allowed_deg, d1=d1, d2=d2)


def raise_missing(model, names) -> None:
    """Report fields that one form of a brief requires as pydantic's own "missing" errors
    (each at its field; the description says which form needs it)."""
    if not names:
        return
    from pydantic import ValidationError
    from pydantic_core import InitErrorDetails

    raise ValidationError.from_exception_data(type(model).__name__, [InitErrorDetails(
        type="missing", loc=(name,), input=None) for name in names])

"""The guide-bar (quick-return) synthesis section shared by the shaper and the slotter:
formulas with the numbers substituted and the link-length table (strings only)."""
from __future__ import annotations

import numpy as np

from .fmt import f

DEG = 180.0 / np.pi


def guide_bar_context(syn, p, rod: str = "BF", ram_zh: str = "刨头",
                      extra_rows: list | None = None) -> dict:
    """``syn``: the synthesis stage (design, extreme angle); ``p``: the SI parameters
    (time ratio, stroke, rod and CoM ratios); ``rod``: the rod's joint letters."""
    d = syn.design
    mm = 1e3
    K, H = p.time_ratio_K, p.stroke * mm
    theta = syn.extreme_angle * DEG
    half = theta / 2
    sin_half = np.sin(np.radians(half))
    eq = {
        "theta": (rf"\theta = 180° \times \frac{{K-1}}{{K+1}} = 180° \times "
                  rf"\frac{{{f(K, 2)}-1}}{{{f(K, 2)}+1}} = {f(theta, 2)}°"),
        "bar": (rf"L_{{O_3B}} = \frac{{H}}{{2\sin(\psi/2)}} = \frac{{{f(H, 0)}}}"
                rf"{{2\sin {f(half, 3)}°}} = {f(d.guide_bar * mm, 2)}\ \text{{mm}}"),
        "crank": (rf"L_{{O_2A}} = L_{{O_2O_3}} \sin(\psi/2) = {f(d.frame * mm, 0)} \times "
                  rf"{f(sin_half, 5)} = {f(d.crank * mm, 2)}\ \text{{mm}}"),
        "rod": (rf"L_{{{rod}}} = {f(p.rod_ratio, 2)}\, L_{{O_3B}} = {f(p.rod_ratio, 2)} \times "
                rf"{f(d.guide_bar * mm, 2)} = {f(d.rod * mm, 2)}\ \text{{mm}}"),
        "guide": (rf"L_{{O_3M}} = L_{{O_3B}}\,\frac{{1+\cos(\psi/2)}}{{2}} = "
                  rf"{f(d.guide_bar * mm, 2)} \times \frac{{1+{f(np.cos(np.radians(half)), 5)}}}{{2}}"
                  rf" = {f(d.guide_height * mm, 2)}\ \text{{mm}}"),
        "com": (rf"L_{{O_3S_4}} = {f(p.com_ratio, 2)}\, L_{{O_3B}} = {f(d.bar_com * mm, 2)}\ \text{{mm}}"),
    }
    rows = [
        ["$\\theta = \\psi$", "极位夹角 = 导杆摆角 / extreme angle = swing", f(theta, 3), "°"],
        ["$L_{O_2A}$", "曲柄 / crank", f(d.crank * mm, 2), "mm"],
        ["$L_{O_3B}$", "导杆 / guide bar", f(d.guide_bar * mm, 2), "mm"],
        [f"$L_{{{rod}}}$", "连杆 / rod", f(d.rod * mm, 2), "mm"],
        ["$L_{O_3M}$", "导路至 O3 / guide line from O3", f(d.guide_height * mm, 2), "mm"],
        *(extra_rows or []),
        ["$L_{O_3S_4}$", "导杆质心 / bar CoM", f(d.bar_com * mm, 2), "mm"],
    ]
    return {"eq": eq, "rows": rows, "ram_zh": ram_zh, "theta": f(theta, 2)}

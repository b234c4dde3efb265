"""Slotting machine (插床): the shaper's guide-bar six-bar with a vertical ram that cuts on
its downward (slow) working stroke. The whole machine is this package: its brief
(:mod:`.brief`), its model and stages (:mod:`.stages`) and its report (:mod:`.report`);
everything else is the shared engine, stages and report sections.
"""
from ...registry import _DEG, _MM, Entry

_P = __name__
ENTRY = Entry(
    name="slotter", brief=f"{_P}.brief:SlotterBrief", to_params=f"{_P}.brief:to_si",
    stages=f"{_P}.stages:stages", document=f"{_P}.stages:results_document",
    report=f"{_P}.report", example="slotter.yaml", results=f"{_P}.stages:SlotterResults",
    summary=(("曲柄", "crank", "mm", "synthesis.crank", _MM),
             ("导杆", "guide bar", "mm", "synthesis.guide_bar", _MM),
             ("K（仿真）", "K (simulated)", "", "linkage.verification.time_ratio", 1.0),
             ("最大压力角", "max pressure angle", "°", "linkage.quality.0.extreme", _DEG),
             ("飞轮 J_F", "flywheel J_F", "kg·m²", "flywheel.inertia", 1.0),
             ("平均功率", "mean power", "W", "linkage.mean_power", 1.0),
             ("电动机", "motor", "", "drive.motor.designation", 1.0)))

"""Clean layers (issue 17, point 4): the render package only reads results, and the
package's modules import each other without cycles (function-level imports included).

* Every ``import`` of every ``src/mechdesign/render/*.py`` (anywhere in the module) that
  reaches into ``mechdesign.core`` or ``mechdesign.machines`` must import a name listed in
  :data:`RENDER_MAY_IMPORT`, each with the reason it computes nothing; importing a whole
  core/machines module (``from ..core import cam``) is refused, since it would give access
  to every function in it.
* ``tools/import_graph.py`` builds the module graph by AST (every import statement, also
  inside functions; importing ``a.b.c`` also depends on ``a/__init__`` and ``a/b/__init__``)
  and its strongly connected components must be empty once the edges of
  :data:`EDGES_BEING_REMOVED` are left out. The tool itself is checked on a small package
  made here whose only cycle goes through a function-level import and a package
  ``__init__``.
"""
from __future__ import annotations

import ast
import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
RENDER = SRC / "mechdesign" / "render"

# (module, name) → why importing it into render computes nothing.
RENDER_MAY_IMPORT = {
    # constants and names
    ("mechdesign.core.cam", "DWELL"): "segment kind constant (a string)",
    ("mechdesign.core.cam", "RISE"): "segment kind constant (a string)",
    ("mechdesign.core.cam", "RETURN"): "segment kind constant (a string)",
    ("mechdesign.core.motion_laws", "LAWS"): "table of the laws' names and coefficients; render "
                                             "reads name_zh/name_en/ca, never calls a law",
    ("mechdesign.core.cycle", "STATES"): "names of the actuator states (zh, en)",
    ("mechdesign.core.cycle", "TWO_PI"): "the constant 2π",
    ("mechdesign.core.cycle", "resolve"): "looks a phase up in the diagram by its reference "
                                          "(actuator, state, occurrence): a look-up, no computation",
    ("mechdesign.core.strength", "COURSE_SCALE"): "a constant of the strength checks",
    ("mechdesign.core.polygons", "spread"): "the extent of a set of drawn points along and across "
                                            "their main line (np.ptp on a rotated copy): the "
                                            "shared measure of a flat polygon, no result",
    ("mechdesign.stages.cam", "CAM_CHECK_NAMES"): "names of the self-checks (zh, en)",
    ("mechdesign.stages.drive", "DRIVE_CHECK_NAMES"): "names of the self-checks (zh, en)",
    ("mechdesign.stages.drive", "shaft_numeral"): "the shafts' numbering (0, Ⅰ, Ⅱ …): a look-up "
                                                 "shared by the tables, warnings and sheets",
    ("mechdesign.stages.drive_strength", "part_message"): "a shaft part's name from its stored "
                                                          "code (a catalogue message): a look-up",
    ("mechdesign.machines.eccentric_cam.stages", "DISC_CHECK_NAMES"): "names of the self-checks (zh, en)",
    ("mechdesign.stages.cam", "DIST_LIMIT"): "a tolerance constant printed with its check",
    # names and messages stored as codes (issue 22 point 3), made into text where shown
    ("mechdesign.stages.findings", "Named"): "a name looked up in a data table by its row key",
    ("mechdesign.stages.findings", "decode"): "a message stored as data ({msgid, args}) as a message",
    ("mechdesign.stages.linkage", "link_name"): "a link's or group's name: the machine's catalogue "
                                               "message translated, or the brief's (zh, en) pair",
    ("mechdesign.stages.findings", "check_name"): "a strength check's name: its msgid and stored fields "
                                                  "as a message",
    # result and model types (isinstance checks and annotations)
    ("mechdesign.core.cam", "TranslatingFollower"): "follower type (isinstance)",
    ("mechdesign.core.cam", "OscillatingFollower"): "follower type (isinstance)",
    ("mechdesign.core.cycle", "CycleDiagram"): "result type (annotations)",
    ("mechdesign.stages.graphical", "GraphicalDocument"): "result type (isinstance: finds the "
                                                          "graphical method's results)",
    ("mechdesign.core.cycle", "PhaseRef"): "result type (annotations)",
    ("mechdesign.core.cycle", "Constraint"): "result type (annotations)",
    ("mechdesign.core.gears", "SpurPair"): "result type (annotations)",
    ("mechdesign.core.mechanism", "Crank"): "Assur group type (isinstance)",
    ("mechdesign.core.mechanism", "RRR"): "Assur group type (isinstance)",
    ("mechdesign.core.mechanism", "RRP"): "Assur group type (isinstance)",
    ("mechdesign.core.mechanism", "RPR"): "Assur group type (isinstance)",
    ("mechdesign.core.mechanism", "LinkPoint"): "Assur group type (isinstance)",
    ("mechdesign.core.strength", "Check"): "result type (annotations)",
    ("mechdesign.stages.cam", "Division"): "result type (annotations)",
    ("mechdesign.stages.gear", "GearDrawing"): "result type (annotations)",
    ("mechdesign.core.polygons", "Polygon"): "result type (annotations)",
    ("mechdesign.stages.polygons", "LinkagePolygons"): "result type (isinstance)",
    # Which points each link carries, read off the model's groups for the drawings (no
    # physics): each group type states its members (core.mechanism), this collects them.
    ("mechdesign.stages.linkage", "link_members"): "topology of the drawing, no physics",
}

def _tool():
    spec = importlib.util.spec_from_file_location("import_graph", ROOT / "tools" / "import_graph.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _absolute(module: str, node: ast.ImportFrom) -> str:
    if not node.level:
        return node.module or ""
    base = module.split(".")[:-node.level]          # a render module is a plain module
    return ".".join(base + ([node.module] if node.module else []))


def _render_imports():
    """(file, line, module imported from, name) of every import in the render package that
    reaches core, stages or machines; name None for a whole-module import."""
    out = []
    for path in sorted(RENDER.glob("*.py")):
        module = "mechdesign.render." + path.stem
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    out.append((path.name, node.lineno, alias.name, None))
            elif isinstance(node, ast.ImportFrom):
                base = _absolute(module, node)
                for alias in node.names:
                    if base in ("mechdesign", "mechdesign.core", "mechdesign.machines",
                                "mechdesign.stages"):
                        out.append((path.name, node.lineno, f"{base}.{alias.name}", None))
                    else:
                        out.append((path.name, node.lineno, base, alias.name))
    return [x for x in out
            if x[2].startswith(("mechdesign.core", "mechdesign.machines", "mechdesign.stages"))]


def test_render_imports_nothing_that_computes():
    found = _render_imports()
    assert found, "the scan found no import at all: it is not reading the render package"
    bad = [f"{f}:{line}: {mod}" + ("" if name is None else f".{name}")
           + (" (a whole module)" if name is None else "")
           for f, line, mod, name in found if (mod, name) not in RENDER_MAY_IMPORT]
    assert not bad, "render imports computation from core/machines:\n" + "\n".join(bad)


def test_render_allow_list_is_used():
    """Every allowed name is still imported somewhere (a stale entry would hide nothing
    today but allow a computation tomorrow)."""
    used = {(mod, name) for _, _, mod, name in _render_imports()}
    assert set(RENDER_MAY_IMPORT) <= used, sorted(set(RENDER_MAY_IMPORT) - used)


def test_scan_catches_a_computational_import(tmp_path, monkeypatch):
    """The scan refuses a function import and a whole-module import (checked on a copy)."""
    fake = tmp_path / "src" / "mechdesign" / "render"
    fake.mkdir(parents=True)
    (fake / "bad.py").write_text("def f():\n    from ..core.cam import design_cam\n"
                                 "from ..core import cam\n", encoding="utf-8")
    monkeypatch.setattr(sys.modules[__name__], "RENDER", fake)
    found = {(mod, name) for _, _, mod, name in _render_imports()}
    assert ("mechdesign.core.cam", "design_cam") in found
    assert ("mechdesign.core.cam", None) in found
    assert not found & set(RENDER_MAY_IMPORT)


def test_import_graph_has_no_cycles():
    tool = _tool()
    graph = tool.graph(SRC)
    assert "mechdesign.render.cam_sheet" in graph and len(graph) > 50
    # brief → machines → brief would be the classic one: the brief layer imports no machine
    assert not any(b.startswith("mechdesign.machines") for a, bs in graph.items()
                   if a.startswith("mechdesign.brief") for b in bs)
    cycles = tool.cycles(graph)
    assert cycles == [], "import cycles:\n" + "\n".join(", ".join(c) for c in cycles)


def test_computation_imports_no_render():
    """core, stages, machines' stage modules and mechdesign.numbers (the number rule's digits,
    shared with render) reach no render module, directly or through another module."""
    tool = _tool()
    graph = tool.graph(SRC)
    assert "mechdesign.numbers" in graph["mechdesign.render.fmt"]
    assert "mechdesign.numbers" in graph["mechdesign.stages.drive_strength"]
    start = [m for m in graph if m.startswith(("mechdesign.core", "mechdesign.stages"))
             or m == "mechdesign.numbers" or m.endswith(".stages")]
    bad = []
    for m in start:
        seen, todo = set(), [m]
        while todo:
            x = todo.pop()
            for y in graph.get(x, ()):
                if y.startswith("mechdesign.render"):
                    bad.append(f"{m} → … {x} → {y}")
                elif y not in seen:
                    seen.add(y)
                    todo.append(y)
    assert not bad, "\n".join(sorted(set(bad))[:20])


def test_import_graph_command_line():
    args = [sys.executable, str(ROOT / "tools" / "import_graph.py")]
    run = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    assert " 0 cycle(s)" in run.stdout


@pytest.fixture
def toy(tmp_path):
    """pkg/a.py imports pkg.sub.b inside a function; pkg/sub/__init__.py imports pkg.a:
    a cycle only through a function-level import and a package __init__."""
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("", encoding="utf-8")
    (pkg / "a.py").write_text("import os\n\ndef f():\n    from .sub.b import g\n    return g\n",
                              encoding="utf-8")
    (pkg / "sub" / "__init__.py").write_text("from .. import a\n", encoding="utf-8")
    (pkg / "sub" / "b.py").write_text("def g():\n    return 1\n", encoding="utf-8")
    (pkg / "c.py").write_text("from pkg.sub import b\n", encoding="utf-8")
    return tmp_path


def test_tool_sees_function_level_and_package_imports(toy):
    tool = _tool()
    g = tool.graph(toy, "pkg")
    assert g["pkg.a"] == {"pkg.sub", "pkg.sub.b"}          # os ignored; sub's __init__ added
    assert g["pkg.sub"] == {"pkg.a"}
    assert g["pkg.sub.b"] == set()                         # its own package is already loaded
    assert g["pkg.c"] == {"pkg.sub", "pkg.sub.b"}
    assert tool.cycles(g) == [["pkg.a", "pkg.sub"]]
    assert tool.cycles(tool.without(g, {("pkg.a", "pkg.sub")})) == []


def test_check_of_every_example_runs_no_engine_and_imports_no_numpy():
    """`mechdesign check` validates without computing (issue 17, point 4): in one fresh
    interpreter, checking every example (every group) leaves numpy, the linkage engine and the
    machines' stages unimported — the closed-form rules between fields are plain arithmetic.
    (How long a check takes is measured by benchmarks/bench_check.py.)"""
    script = r"""
import sys
from pathlib import Path
from typer.testing import CliRunner
from mechdesign.cli import app
heavy = ("numpy", "scipy", "matplotlib", "mechdesign.core.mechanism", "mechdesign.core.cam",
         "mechdesign.core.cycle", "mechdesign.core.fourbar", "mechdesign.pipeline")
for path in sorted(Path(sys.argv[1]).glob("*.yaml")):
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 0, (path, result.output)
    loaded = [m for m in heavy if m in sys.modules]
    loaded += [m for m in sys.modules if m.startswith("mechdesign.") and m.endswith(".stages")]
    assert not loaded, (path.name, loaded)
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", script, str(ROOT / "designs")],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr[-2000:]

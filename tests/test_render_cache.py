"""The render cache (mechdesign/render/cache.py): a figure's key is its state, the same
in every process and under every hash seed, changes with the figure's data and text, and
a run served from the cache writes the same bytes as a run that draws everything."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

_KEY = r"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import FuncFormatter
from mechdesign.render import cache
from mechdesign.render.fonts import configure_matplotlib

configure_matplotlib()
scale = float(sys.argv[1])
fig, axes = plt.subplots(2, 1, figsize=(7, 4), sharex=True, dpi=150)
x = np.linspace(0, 360, 361)
for ax in axes:
    ax.plot(x, scale * np.sin(np.radians(x)))
    ax.axvspan(0, 200, color="0.93")
    ax.set_ylabel(sys.argv[2])
top = axes[0].secondary_xaxis("top")
top.set_xticks([30, 90])
axes[1].yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v * scale:.1f}"))
axes[1].annotate("", xy=(10, 0.5), xytext=(90, 0.2), arrowprops=dict(arrowstyle="<->"))
plt.close(fig)        # as a background save sees it: no longer held by pyplot
print(cache.figure_key(fig, "test"))
"""


def _key(tmp_path, scale="1.0", label="速度 v (m/s)", seed="0") -> str:
    env = {"MECHDESIGN_CACHE": str(tmp_path / "c"), "PYTHONHASHSEED": seed,
           "MPLBACKEND": "Agg", "PATH": "/usr/bin:/bin"}
    out = subprocess.run([sys.executable, "-c", _KEY, scale, label], env=env, cwd=ROOT,
                         capture_output=True, text=True, check=True)
    return out.stdout.strip()


def test_figure_key_is_the_same_in_every_process(tmp_path):
    first = _key(tmp_path, seed="1")
    assert len(first) == 64
    assert _key(tmp_path, seed="2") == first


def test_figure_key_changes_with_data_text_and_closure(tmp_path):
    base = _key(tmp_path)
    assert _key(tmp_path, scale="1.001") != base          # data and the formatter's closure
    assert _key(tmp_path, label="velocity v (m/s)") != base


def test_off_means_no_key(monkeypatch):
    from mechdesign.render import cache

    monkeypatch.setenv("MECHDESIGN_CACHE", "off")
    assert cache.folder() is None
    assert cache.figure_key(object(), "x") is None
    assert cache.typst_key("x", None) is None


def test_typst_key_covers_the_files_under_root(tmp_path, monkeypatch):
    from mechdesign.render import cache

    monkeypatch.setenv("MECHDESIGN_CACHE", str(tmp_path / "c"))
    root = tmp_path / "root"
    (root / "figures").mkdir(parents=True)
    (root / "figures" / "a.png").write_bytes(b"one")
    key = cache.typst_key("#image(\"figures/a.png\")", root, timestamp=0)
    assert cache.typst_key("#image(\"figures/a.png\")", root, timestamp=0) == key
    assert cache.typst_key("#image(\"figures/a.png\")", root, timestamp=1) != key
    (root / "figures" / "a.png").write_bytes(b"two")
    assert cache.typst_key("#image(\"figures/a.png\")", root, timestamp=0) != key


@pytest.mark.e2e
def test_a_cached_run_writes_the_same_files(tmp_path):
    """Cold (cache off), then twice with the cache (filling it, then served from it):
    every file of the three outputs is byte-identical."""
    import os

    outs = []
    for k, setting in enumerate(("off", str(tmp_path / "cache"), str(tmp_path / "cache"))):
        env = dict(os.environ, MECHDESIGN_CACHE=setting, MPLBACKEND="Agg")
        out = tmp_path / f"out{k}"
        subprocess.run([sys.executable, "-m", "mechdesign", "run", "designs/cam_7_1.yaml",
                        "-o", str(out)], env=env, cwd=ROOT, check=True, capture_output=True)
        outs.append(out)
    files = sorted(p.relative_to(outs[0]) for p in outs[0].rglob("*") if p.is_file())
    assert any(p.suffix == ".png" for p in files) and any(p.suffix == ".pdf" for p in files)
    for other in outs[1:]:
        assert sorted(p.relative_to(other) for p in other.rglob("*") if p.is_file()) == files
        for rel in files:
            assert (other / rel).read_bytes() == (outs[0] / rel).read_bytes(), rel
    assert any((tmp_path / "cache").rglob("*"))


_SERVICE = r"""
import sys
from pathlib import Path
from mechdesign.render import parallel, pdf

tmp = Path(sys.argv[1])
src = "#set page(width: 50mm, height: 30mm)\nHello $x^2$"
stop = pdf.start_service()
try:
    assert set(pdf._service_address) == {"file", "bytes"}
    pdf.compile_pdf(src, tmp, tmp / "served.pdf", {"date": "1970-01-01"})
    assert not parallel.typst_used()
    try:
        pdf.compile_pdf("#let x = (", tmp, tmp / "bad.pdf", {})
    except pdf.PdfRenderError as exc:
        assert "typst failed" in str(exc)
    else:
        raise AssertionError("no error")
    assert not (tmp / "bad.pdf").exists()
finally:
    stop()
assert pdf._service_address == {}
pdf.compile_pdf(src, tmp, tmp / "here.pdf", {"date": "1970-01-01"})
assert parallel.typst_used()
assert pdf.start_service()() is None      # after typst ran here: no service, a no-op stop
assert pdf._service_address == {}
print("ok")
"""


def test_the_warm_typst_process_compiles_for_this_one(tmp_path):
    """mechdesign watch's compiling process (render/pdf.py start_service), in a fresh
    interpreter (a process that has run typst must not fork one): the PDF is the one
    typst makes in the process itself, an error in the source comes back as
    PdfRenderError, the process is not marked as having run typst (it may still fork);
    after stop() it compiles itself, and then starts no service."""
    import os

    if not sys.platform.startswith("linux"):
        pytest.skip("the compiling process is forked (Linux)")
    env = dict(os.environ, MECHDESIGN_CACHE="off")
    out = subprocess.run([sys.executable, "-c", _SERVICE, str(tmp_path)], env=env, cwd=ROOT,
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr
    assert (tmp_path / "served.pdf").read_bytes() == (tmp_path / "here.pdf").read_bytes()


_MEMO = r"""
import os, sys
from pathlib import Path
from mechdesign.render import pdf

def children_cpu():           # CPU seconds of this process's children (the services)
    total = 0
    for task in Path(f"/proc/{os.getpid()}/task").iterdir():
        for pid in (task / "children").read_text().split():
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])
    return total / os.sysconf("SC_CLK_TCK")

tmp = Path(sys.argv[1])
body = "\n\n".join(f"== Section {i}\n" + " ".join(f"word{j} $x_{j}^2$" for j in range(100))
                   for i in range(60))
src = '#set page(height: 200mm)\n#set heading(numbering: "1.")\n#outline()\n' + body
stop = pdf.start_service()
try:
    c0 = children_cpu()
    pdf.compile_pdf(src, tmp, tmp / "a.pdf", {})
    cold = children_cpu() - c0
    for i in range(12):      # a run's drawing sheets: a PDF and a PNG preview of each
        pdf.cached_compile(f"#set page(width: 40mm, height: 20mm)\nsheet {i}".encode(),
                           format="png", ppi=30)
    c0 = children_cpu()
    pdf.compile_pdf(src, tmp, tmp / "b.pdf", {})
    warm = children_cpu() - c0
finally:
    stop()
print(cold, warm)
"""


def test_the_reports_compiling_process_keeps_its_memo_across_the_sheets(tmp_path):
    """typst forgets what a compilation memoised once ~10 later compilations of the
    process have not used it; a run compiles up to six sheets twice (PDF and preview)
    between two reports. In the watch the report's compiling process does only reports,
    so the same report compiled again after twelve sheet compilations takes a fraction of
    its first compilation's CPU time (through one shared process: about all of it)."""
    import os

    if not sys.platform.startswith("linux"):
        pytest.skip("the compiling processes are forked (Linux, /proc)")
    env = dict(os.environ, MECHDESIGN_CACHE="off")
    out = subprocess.run([sys.executable, "-c", _MEMO, str(tmp_path)], env=env, cwd=ROOT,
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    cold, warm = map(float, out.stdout.split())
    assert cold >= 0.1, (cold, warm)           # enough to measure at the clock's 10 ms
    assert warm < 0.5 * cold, (cold, warm)
    assert (tmp_path / "a.pdf").read_bytes() == (tmp_path / "b.pdf").read_bytes()


def test_trimming_removes_only_the_caches_own_entries(tmp_path, monkeypatch):
    """A cache folder set to a folder that holds other files: trimming (here to 0 bytes)
    removes the entries the cache wrote and nothing else (a run never deletes a file it did
    not write)."""
    from mechdesign.render import cache

    theirs = [tmp_path / "notes.txt", tmp_path / "ab" / "thesis.docx", tmp_path / "photos" / "a.png",
              tmp_path / "ab" / ("ab" + "0" * 61)]          # 63 hex digits: not an entry name
    for path in theirs:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(b"x" * 1000)
    monkeypatch.setenv("MECHDESIGN_CACHE", str(tmp_path))
    monkeypatch.setattr(cache, "LIMIT_BYTES", 0)
    monkeypatch.setattr(cache, "_trimmed", True)         # no trim while storing
    key = "ab" + "1" * 62
    cache.store(key, b"entry")
    assert (tmp_path / "ab" / key).read_bytes() == b"entry"
    monkeypatch.setattr(cache, "_trimmed", False)
    cache._trim_once(tmp_path)
    assert not (tmp_path / "ab" / key).exists()
    assert all(path.read_bytes() == b"x" * 1000 for path in theirs)


def test_a_load_edit_keeps_the_cache_keys_of_the_kinematic_polygon_figures(
        example_results, tmp_path, monkeypatch):
    """A figure is keyed by its call (render/cache.py call_key): the graphical method's
    velocity/acceleration figures must be given what they draw only, so that a changed
    cutting force (which changes no velocity or acceleration: the kinematics do not depend
    on the loads) finds them in the cache instead of building them again (watch)."""
    import re

    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages
    from mechdesign.render import cache
    from mechdesign.render import graphical_report as G

    monkeypatch.setenv("MECHDESIGN_CACHE", str(tmp_path / "cache"))
    text = (ROOT / "designs" / "shaper.yaml").read_text(encoding="utf-8")
    edited, n = re.subn(r"^(  cutting_force_Fc_N: )1600$", r"\g<1>1700", text, flags=re.M)
    assert n == 1
    (tmp_path / "shaper.yaml").write_text(edited, encoding="utf-8")
    brief = load_brief(tmp_path / "shaper.yaml")
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    loaded, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})

    kin = G._kin_figure.__wrapped__           # the drawing function under the cache

    def keys(results) -> dict[str, str]:
        found = {}

        def record(path, *args, **kwargs):
            found[Path(path).name] = cache.call_key(kin, args, kwargs)

        monkeypatch.setattr(G, "_kin_figure", record)
        monkeypatch.setattr(G, "_force_figure", lambda *a, **k: None)
        G.graphical_figures(results, tmp_path, "zh")
        return found

    before, after = keys(example_results("shaper")), keys(loaded)
    assert before and all(before.values()) and before.keys() == after.keys()
    assert before == after

"""`mechdesign watch` writes the same report.pdf as a plain `mechdesign run` (issue 22 point 4):
the watch compiles in a warm typst process (render/pdf.py start_service), re-using the
layout of what an edit left unchanged and the figures of the render cache; the bytes must
not depend on that. The reference is a run in a fresh process with the render cache off."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import wait_until

from mechdesign.render.pdf import _source_file

ROOT = Path(__file__).resolve().parents[1]


def test_the_typst_source_keeps_its_name_from_run_to_run(tmp_path):
    # typst memoises by file identity: the warm process re-uses a layout only for a source
    # of the same name (a staging folder is new for each run, the name within it is not)
    for folder in (tmp_path / "a", tmp_path / "b"):
        folder.mkdir()
        fd, name = _source_file(folder, "report")
        os.close(fd)
        assert Path(name) == folder / ".report.typ"
    # the name taken (a compilation in the same folder at the same time): another one
    fd, other = _source_file(tmp_path / "a", "report")
    os.close(fd)
    assert Path(other).parent == tmp_path / "a" and Path(other).name != ".report.typ"


def _wait(predicate, timeout: float, proc) -> None:
    wait_until(predicate, timeout, proc, step=0.05)


def _stamp(path: Path):
    try:
        st = path.stat()
        return st.st_ino, st.st_mtime_ns
    except OSError:
        return None


@pytest.mark.e2e
def test_watch_pdf_is_byte_identical_to_a_plain_run(tmp_path):
    brief = tmp_path / "cam.yaml"
    text = (ROOT / "designs" / "cam_7_3.yaml").read_text(encoding="utf-8")
    assert "base_radius_mm: 50 " in text
    brief.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    pdf = out / "report.pdf"
    env = {**os.environ, "MPLBACKEND": "Agg", "MECHDESIGN_CACHE": str(tmp_path / "cache")}
    log = tmp_path / "stderr.txt"
    with open(log, "w", encoding="utf-8") as err:
        proc = subprocess.Popen([sys.executable, "-m", "mechdesign", "watch", str(brief),
                                 "--format", "md,pdf", "-o", str(out)],
                                stdout=subprocess.DEVNULL, stderr=err, env=env)
    try:
        _wait(lambda: pdf.exists(), 300, proc)
        # two edits: the second compilation of each is incremental in the warm process
        for value in ("55", "50.5"):
            before = _stamp(pdf)
            brief.write_text(text.replace("base_radius_mm: 50 ", f"base_radius_mm: {value} "),
                             encoding="utf-8")
            _wait(lambda: _stamp(pdf) != before, 300, proc)
    finally:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            proc.kill()
            raise
    assert "Traceback" not in log.read_text(encoding="utf-8")
    plain = tmp_path / "plain"
    subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "--format", "md,pdf",
                    "-o", str(plain)], check=True, capture_output=True,
                   env={**env, "MECHDESIGN_CACHE": "off"})
    assert (plain / "report.pdf").read_bytes() == pdf.read_bytes()
    assert (plain / "report.md").read_bytes() == (out / "report.md").read_bytes()

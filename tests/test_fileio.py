"""The one atomic-write helper (issue 17, point 6): the old file survives a failing
writer, no temporary file is left behind, a concurrent reader never sees a partial file,
bytes stay bytes and text keeps its encoding."""
from __future__ import annotations

import os
import re
import stat
import threading
from pathlib import Path

import pytest

from mechdesign.fileio import atomic_open, atomic_path, write_bytes, write_text


class Boom(Exception):
    pass


def _leftovers(folder):
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


@pytest.mark.parametrize("exc", [Boom("writer failed"), KeyboardInterrupt()],
                         ids=["exception", "KeyboardInterrupt"])
@pytest.mark.parametrize("variant", ["open-text", "open-bytes", "path"])
def test_a_failing_writer_leaves_the_old_file_and_no_temporary(tmp_path, exc, variant):
    target = tmp_path / "report.md"
    target.write_bytes(b"old content\n")
    with pytest.raises(type(exc)):
        if variant == "path":
            with atomic_path(target) as tmp:
                tmp.write_bytes(b"half of the new")
                raise exc
        else:
            with atomic_open(target, "w" if variant == "open-text" else "wb") as fh:
                fh.write("half of the new" if variant == "open-text" else b"half of the new")
                fh.flush()
                raise exc
    assert target.read_bytes() == b"old content\n"
    assert _leftovers(tmp_path) == []


def test_a_failing_writer_of_a_new_file_leaves_nothing(tmp_path):
    with pytest.raises(Boom):
        with atomic_path(tmp_path / "sub" / "sheet.dxf") as tmp:
            tmp.write_text("partial")
            raise Boom
    assert list((tmp_path / "sub").iterdir()) == []


def test_a_library_that_recreates_the_file_is_published(tmp_path):
    """Writers such as pandoc may delete and recreate the file at the temporary path;
    the temporary name keeps the target's suffix (matplotlib picks the format by it)."""
    target = tmp_path / "figure.png"
    with atomic_path(target) as tmp:
        assert tmp.parent == tmp_path and tmp.suffix == ".png" and tmp.name.startswith(".")
        assert tmp.exists() and not target.exists()
        tmp.unlink()
        tmp.write_bytes(b"\x89PNG new")
    assert target.read_bytes() == b"\x89PNG new"
    assert _leftovers(tmp_path) == []


def test_bytes_and_text_keep_their_content_type(tmp_path):
    data = bytes(range(256)) * 3 + b"\r\n\x00"
    assert write_bytes(tmp_path / "a.bin", data) == tmp_path / "a.bin"
    assert (tmp_path / "a.bin").read_bytes() == data

    text = "曲柄 ω₁ = 6.28 rad/s — Ø50\n第二行\n"
    write_text(tmp_path / "u8.md", text)                         # UTF-8 by default
    assert (tmp_path / "u8.md").read_bytes() == text.encode("utf-8")
    write_text(tmp_path / "gbk.txt", text.replace("ω₁", "w1").replace("—", "-").replace("Ø", "D"),
               encoding="gb18030")
    assert (tmp_path / "gbk.txt").read_bytes() == (
        "曲柄 w1 = 6.28 rad/s - D50\n第二行\n".encode("gb18030"))
    write_text(tmp_path / "crlf.csv", "a,b\nc,d\n", newline="\r\n")
    assert (tmp_path / "crlf.csv").read_bytes() == b"a,b\r\nc,d\r\n"
    with atomic_open(tmp_path / "raw.csv", "w", newline="") as fh:   # csv module's way
        fh.write("x\r\ny\n")
    assert (tmp_path / "raw.csv").read_bytes() == b"x\r\ny\n"

    with pytest.raises(TypeError):
        write_bytes(tmp_path / "c.bin", "text is not bytes")
    with pytest.raises(TypeError):
        write_text(tmp_path / "c.txt", b"bytes are not text")
    assert not (tmp_path / "c.bin").exists() and not (tmp_path / "c.txt").exists()
    assert _leftovers(tmp_path) == []


def test_permissions_are_ordinary_and_a_replaced_file_keeps_its_mode(tmp_path):
    mask = os.umask(0o022)
    try:
        write_text(tmp_path / "new.md", "x")
        assert stat.S_IMODE((tmp_path / "new.md").stat().st_mode) == 0o644
        old = tmp_path / "old.md"
        old.write_text("old")
        old.chmod(0o600)
        write_text(old, "new")
        assert stat.S_IMODE(old.stat().st_mode) == 0o600 and old.read_text() == "new"
    finally:
        os.umask(mask)


def test_parents_are_made_unless_asked_not_to(tmp_path):
    write_bytes(tmp_path / "a" / "b" / "c.pdf", b"%PDF")
    assert (tmp_path / "a" / "b" / "c.pdf").read_bytes() == b"%PDF"
    with pytest.raises(FileNotFoundError):
        write_text(tmp_path / "missing" / "x.yaml", "a: 1", parents=False)
    assert not (tmp_path / "missing").exists()


def test_a_concurrent_reader_never_sees_a_partial_file(tmp_path):
    """A writer thread replaces a 4 MB file over and over with contents of distinct
    lengths and fill bytes; a reader reading all the while must always find one of the
    complete contents."""
    target = tmp_path / "big.bin"
    size = 4 << 20
    contents = [bytes([k]) * (size + k) for k in range(1, 6)]
    target.write_bytes(contents[0])
    valid = {(len(c), c[:1]) for c in contents}
    stop = threading.Event()
    errors: list[BaseException] = []

    def writer():
        try:
            for round_ in range(12):
                for c in contents:
                    # a slow, chunked writer makes partial states long-lived
                    with atomic_open(target, "wb", fsync=False) as fh:
                        for i in range(0, len(c), 1 << 18):
                            fh.write(c[i:i + (1 << 18)])
        except BaseException as exc:       # noqa: BLE001 - reported by the main thread
            errors.append(exc)
        finally:
            stop.set()

    thread = threading.Thread(target=writer)
    thread.start()
    reads = 0
    while not stop.is_set() or reads == 0:
        data = target.read_bytes()
        reads += 1
        assert (len(data), data[:1]) in valid, f"partial read of {len(data)} bytes"
        assert data == bytes(data[:1]) * len(data)
    thread.join()
    assert not errors, errors
    assert reads > 1
    assert target.read_bytes() == contents[-1]
    assert _leftovers(tmp_path) == []


def test_concurrent_writers_of_one_target_do_not_collide(tmp_path):
    """Threads writing the same file use distinct temporary names; the file ends as one
    writer's complete content."""
    target = tmp_path / "index.json"
    texts = [f'{{"writer": {k}, "pad": "{"x" * 50_000}"}}\n' for k in range(8)]
    threads = [threading.Thread(target=lambda t=t: [write_text(target, t) for _ in range(10)])
               for t in texts]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert target.read_text(encoding="utf-8") in texts
    assert _leftovers(tmp_path) == []


def test_bad_modes_are_refused(tmp_path):
    for mode in ("a", "r", "r+", "x"):
        with pytest.raises(ValueError):
            with atomic_open(tmp_path / "f", mode):
                pass
    assert list(tmp_path.iterdir()) == []


# Writes that are not output files: scratch inputs for pandoc/typst in temporary folders,
# pandoc's captured stderr, and the run's publish step (staging folder → output folder,
# which moves finished files, each move atomic; mechdesign.publish).
_NOT_OUTPUT = {
    "render/pdf.py": ('(tmp / "metadata.json").write_text', '(tmp / "typst-literal.lua").write_text',
                      '(tmp / "unit-join.lua").write_text',
                      '(tmp / "in.md").write_text', 'open(self._err, "wb")',
                      'os.fdopen(fd, "w", encoding="utf-8")',
                      # the same scratch source rewritten without the figure rules (_settle's fallback)
                      'open(typ_name, "w", encoding="utf-8")'),
    "render/docx.py": ("meta_file.write_text", "unit_filter.write_text"),
    "publish.py": ("os.replace(staging / rel, target)",),
}
_WRITE = re.compile(r"\.write_text\(|\.write_bytes\(|\bopen\([^)]*[\"'][wax]b?t?[\"']|"
                    r"\.savefig\(|\.saveas\(|\.save\(|os\.replace\(|os\.rename\(|shutil\.(copy|move)")
# a library writing to the temporary path that fileio.atomic_path yields
_TO_ATOMIC_TMP = re.compile(r"\.(savefig|saveas|save)\(tmp\b")


def test_every_output_write_goes_through_fileio():
    """No module writes an output file by itself: every write in the package is a call of
    mechdesign.fileio, a library writing to the path atomic_path gave, or a listed
    scratch/publish step."""
    import mechdesign

    root = Path(mechdesign.__file__).parent
    stray = []
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        if rel == "fileio.py":
            continue
        for no, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            code = line.split("#")[0]
            if not _WRITE.search(code) or _TO_ATOMIC_TMP.search(code):
                continue
            if any(allowed in code for allowed in _NOT_OUTPUT.get(rel, ())):
                continue
            stray.append(f"{rel}:{no}: {line.strip()}")
    assert not stray, "write output files through mechdesign.fileio:\n" + "\n".join(stray)

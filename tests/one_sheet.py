"""One drawing sheet of an example brief, written as DXF and read back (used by
tests/test_cycle_sheet.py and tests/test_transmission_sheet.py)."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def written_sheet(results: dict, name: str, kind: str, tmp_path: Path, lang: str):
    """(modelspace of the written DXF, the sheet's builder) for the sheet ``kind`` ("cycle",
    "transmission", …) of designs/<name>.yaml with its computed ``results``, written by the
    program's own sheet writer into ``tmp_path``."""
    import ezdxf

    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, write_all

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    (tmp_path / "f").mkdir()
    builders = [b for b in _builders(results, brief) if b[0] == kind]
    files = write_all(builders, brief, tmp_path, tmp_path / "f", lang, ("dxf",))
    assert len(files) == 1
    return ezdxf.readfile(tmp_path / files[0].dxf).modelspace(), builders[0][1]

"""Coal's mesh hulls from the mesh parts kept on disk equal the ones from the file bit for
bit (an STL through coal's loader, an OBJ of many parts); a damaged entry is rebuilt."""

from __future__ import annotations

from pathlib import Path

import coal
import numpy as np
import pybullet_data
import pytest

from robocram.motion import coal_shapes

MUG = Path(pybullet_data.getDataPath()) / "objects" / "mug_col.obj"
STL = Path(__file__).parents[1] / "data/stretch/stretch_description/meshes/base_link.STL"
SCALE = (1.0, 0.5, 2.0)


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    return tmp_path / "mesh_parts"


def _arrays(hull: coal.ConvexBase) -> list[np.ndarray]:
    return [
        np.array(hull.points()),
        np.array(hull.normals()),
        np.array(hull.offsets()),
        np.array(hull.center),
    ]


def _computed(file: Path) -> list[list[np.ndarray]]:
    """The hulls straight from the file, as before the disk cache."""
    obj = file.suffix.lower() == ".obj"
    parts = coal_shapes._obj_parts(file) if obj else [coal_shapes._loaded_vertices(file)]
    factor = np.asarray(SCALE)
    return [_arrays(coal_shapes._hull(p * factor, str(file))) for p in parts if len(p) >= 4]


def _kept(file: Path) -> list[list[np.ndarray]]:
    hulls = coal_shapes.mesh_hulls.__wrapped__(str(file), SCALE)  # type: ignore[attr-defined]
    return [_arrays(h) for h in hulls]


def _same(a: list[list[np.ndarray]], b: list[list[np.ndarray]]) -> bool:
    return len(a) == len(b) and all(
        x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes()
        for p, q in zip(a, b, strict=True)
        for x, y in zip(p, q, strict=True)
    )


@pytest.mark.parametrize(("file", "parts"), [(MUG, 6), (STL, 1)])
def test_hulls_from_kept_parts_equal_the_computed_ones(cache: Path, file: Path, parts: int) -> None:
    computed = _computed(file)
    assert len(computed) == parts
    built = _kept(file)
    assert len(list(cache.glob("*.arrays"))) == 1
    assert _same(built, computed) and _same(_kept(file), computed)


def test_a_damaged_entry_is_rebuilt(cache: Path) -> None:
    _kept(STL)
    (entry,) = cache.glob("*.arrays")
    whole = entry.read_bytes()
    entry.write_bytes(b"\0" * len(whole))
    assert _same(_kept(STL), _computed(STL))
    assert entry.read_bytes() == whole

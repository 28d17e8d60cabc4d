"""The lone-ray hulls of a mesh are kept on disk by the file's content: read back they equal
the ones computed bit for bit, a damaged entry is rebuilt, an edited file gets new hulls."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pybullet_data
import pytest

from robocram.world import shape_rays
from robocram.world.shape_rays import Piece

MUG = Path(pybullet_data.getDataPath()) / "objects" / "mug_col.obj"
SCALE = (1.0, 0.5, 2.0)


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache" / "ray_hulls"


def _same(ours: tuple[Piece, ...] | None, theirs: tuple[Piece, ...]) -> bool:
    """Equal bit for bit: kind, radius, and the planes' and boxes' types, shapes and bytes."""
    assert ours is not None
    return len(ours) == len(theirs) and all(
        a.kind == b.kind
        and a.radius == b.radius
        and all(
            x.dtype == y.dtype and x.shape == y.shape and x.tobytes() == y.tobytes()
            for x, y in ((a.planes, b.planes), (a.box, b.box))
        )
        for a, b in zip(ours, theirs, strict=True)
    )


def _hulls(path: Path) -> tuple[Piece, ...] | None:
    """The hulls as a new process gets them (past the per-process cache)."""
    return shape_rays._mesh_hulls.__wrapped__(str(path), SCALE)  # type: ignore[attr-defined]


def test_hulls_read_back_equal_the_computed_ones(cache: Path) -> None:
    computed = shape_rays._mesh_pieces(MUG, SCALE)
    assert len(computed) == 6  # the cup and the handle's pieces
    built = _hulls(MUG)
    assert len(list(cache.glob("*.arrays"))) == 1
    read = _hulls(MUG)
    assert _same(built, computed) and _same(read, computed)


def test_a_damaged_entry_is_rebuilt(cache: Path) -> None:
    _hulls(MUG)
    (entry,) = cache.glob("*.arrays")
    whole = entry.read_bytes()
    entry.write_bytes(whole[: len(whole) // 2])
    assert _same(_hulls(MUG), shape_rays._mesh_pieces(MUG, SCALE))
    assert entry.read_bytes() == whole  # replaced by a whole entry


def test_a_copy_shares_the_entry_and_an_edited_file_gets_its_own(
    cache: Path, tmp_path: Path
) -> None:
    copy = tmp_path / "mug.obj"
    shutil.copyfile(MUG, copy)
    assert _same(_hulls(copy), _hulls(MUG) or ())
    assert len(list(cache.glob("*.arrays"))) == 1
    # the same mesh twice as large: new hulls, not the kept ones
    lines = MUG.read_text().splitlines()
    copy.write_text(
        "\n".join(
            "v " + " ".join(str(2 * float(w)) for w in line.split()[1:4])
            if line.startswith("v ")
            else line
            for line in lines
        )
    )
    edited = _hulls(copy)
    assert edited is not None and len(list(cache.glob("*.arrays"))) == 2
    assert _same(edited, shape_rays._mesh_pieces(copy, SCALE))
    assert not np.array_equal(edited[0].box, (_hulls(MUG) or ())[0].box)


def test_a_vertex_hull_reads_back_equal(cache: Path) -> None:
    points = np.random.default_rng(5).uniform(-0.1, 0.1, size=(40, 3))
    vertices = tuple(tuple(float(v) for v in row) for row in points)
    computed = (shape_rays._hull(points),)
    hull = shape_rays._vertex_hull.__wrapped__  # type: ignore[attr-defined]
    assert _same((hull(vertices),), computed) and _same((hull(vertices),), computed)
    assert len(list(cache.glob("*.arrays"))) == 1

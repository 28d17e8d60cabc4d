"""The disk cache: built once and read back bit for bit, damaged or foreign entries rebuilt,
writers at once leave a whole file; the IK start table and arm slice read from it equal
the ones built."""

from __future__ import annotations

import io
import pickle
import threading
from pathlib import Path

import numpy as np
import pytest

from robocram.kinematics import IKSolver
from robocram.kinematics.seed_table import SeedTable
from robocram.robots import load_description
from robocram.robots.arm_envelope import _working_yaw, working_yaw
from robocram.robots.arm_slice import _flatness, _sampled
from robocram.robots.disk_cache import _MAP_FROM, kept_arrays

KIND = "test-arrays"
BUILT_BY = ("robocram.robots.disk_cache",)


class Builder:
    """Counts its builds; each build gives the same arrays."""

    def __init__(self) -> None:
        self.count = 0

    def __call__(self) -> dict[str, np.ndarray]:
        self.count += 1
        rng = np.random.default_rng(3)
        return {"values": rng.uniform(size=(50, 3)), "cells": np.arange(7, dtype=np.int64)}


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    return tmp_path / KIND


def _same(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> bool:
    return a.keys() == b.keys() and all(
        a[k].dtype == b[k].dtype and a[k].tobytes() == b[k].tobytes() for k in a
    )


def test_built_once_then_read_bit_for_bit(cache: Path) -> None:
    build = Builder()
    first = kept_arrays(KIND, "key", BUILT_BY, build)
    again = kept_arrays(KIND, "key", BUILT_BY, build)
    assert build.count == 1 and _same(first, again) and _same(first, build())
    assert len(list(cache.glob("*.arrays"))) == 1 and not list(cache.glob("*.tmp"))


def test_another_key_or_version_is_another_entry(cache: Path) -> None:
    build = Builder()
    kept_arrays(KIND, "key", BUILT_BY, build)
    kept_arrays(KIND, "other key", BUILT_BY, build)
    kept_arrays(KIND, "key", BUILT_BY, build, versions=("2.0",))
    assert build.count == 3 and len(list(cache.glob("*.arrays"))) == 3


def test_a_cut_short_file_is_rebuilt_and_replaced(cache: Path) -> None:
    build = Builder()
    kept_arrays(KIND, "key", BUILT_BY, build)
    (entry,) = cache.glob("*.arrays")
    entry.write_bytes(entry.read_bytes()[:300])
    assert _same(kept_arrays(KIND, "key", BUILT_BY, build), build())
    assert build.count == 3  # rebuilt (the third call is the comparison's)
    assert _same(kept_arrays(KIND, "key", BUILT_BY, build), build()) and build.count == 4


def _npy() -> bytes:
    out = io.BytesIO()
    np.save(out, np.arange(3.0))
    return out.getvalue()


@pytest.mark.parametrize("junk", [b"", b"not an entry at all", _npy()[:20], _npy()])
def test_a_file_that_is_no_entry_is_rebuilt(cache: Path, junk: bytes) -> None:
    build = Builder()
    kept_arrays(KIND, "key", BUILT_BY, build)
    (entry,) = cache.glob("*.arrays")
    entry.write_bytes(junk)
    assert _same(kept_arrays(KIND, "key", BUILT_BY, build), build()) and build.count == 3


def test_changed_contents_are_not_trusted(cache: Path) -> None:
    build = Builder()
    kept_arrays(KIND, "key", BUILT_BY, build)
    (entry,) = cache.glob("*.arrays")
    data = bytearray(entry.read_bytes())
    at = data.index(np.arange(7, dtype=np.int64).tobytes())  # the cells, as written
    data[at] ^= 0x01  # one bit of the arrays: the CRC no longer matches
    entry.write_bytes(bytes(data))
    assert _same(kept_arrays(KIND, "key", BUILT_BY, build), build()) and build.count == 3


def test_a_read_entry_is_writable_and_owns_no_object(cache: Path) -> None:
    build = Builder()
    kept_arrays(KIND, "key", BUILT_BY, build)
    read = kept_arrays(KIND, "key", BUILT_BY, build)
    assert build.count == 1 and all(a.flags.writeable and a.dtype != object for a in read.values())
    read["values"][0, 0] = -1.0  # changed in place, as an array np.load read could be
    assert _same(kept_arrays(KIND, "key", BUILT_BY, build), build())


def test_a_large_entry_is_mapped_read_bit_for_bit_and_written_to_no_file(cache: Path) -> None:
    def build() -> dict[str, np.ndarray]:  # 2.4 MB: above the size from which files are mapped
        return {"table": np.random.default_rng(5).uniform(size=(100_000, 3))}

    kept_arrays(KIND, "large", BUILT_BY, build)
    (entry,) = cache.glob("*.arrays")
    assert entry.stat().st_size > _MAP_FROM
    on_disk = entry.read_bytes()
    read = kept_arrays(KIND, "large", BUILT_BY, build)
    assert _same(read, build()) and read["table"].flags.writeable
    read["table"][0, 0] = -1.0  # copy on write: the process's pages change, not the file
    assert entry.read_bytes() == on_disk
    again = kept_arrays(KIND, "large", BUILT_BY, build)
    assert _same(again, build()) and again["table"][0, 0] != -1.0


def test_writers_at_once_leave_a_whole_file(cache: Path) -> None:
    build = Builder()
    threads = [
        threading.Thread(target=kept_arrays, args=(KIND, "key", BUILT_BY, build)) for _ in range(8)
    ]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    built = build.count
    assert _same(kept_arrays(KIND, "key", BUILT_BY, build), build())
    assert build.count == built + 1  # read from the file, the comparison built once more
    assert len(list(cache.glob("*.arrays"))) == 1 and not list(cache.glob("*.tmp"))


def test_start_table_read_equals_built(cache: Path) -> None:
    solver = IKSolver.cached(load_description("pr2"), "right")
    built = SeedTable(solver.chain, 2000, solver.reach.radius)
    assert len(list((cache.parent / "seed-tables").glob("*.arrays"))) == 1
    read = SeedTable(solver.chain, 2000, solver.reach.radius)
    for name in ("configurations", "features", "_keys_sorted", "_squares", "_low", "_shape"):
        a, b = getattr(built, name), getattr(read, name)
        assert a.dtype == b.dtype and a.tobytes() == b.tobytes(), name
    assert read.cell == built.cell


def test_arm_flatness_read_equals_computed(cache: Path) -> None:
    pr2 = load_description("pr2")
    assert pr2.model is not None
    arm = pr2.arms["right"]
    joints = tuple(j for j in arm.joints if pr2.model.joints[j].mimic is None)
    computed = _sampled(pr2.model, arm.end_effector_link, joints)
    assert _flatness(pr2.model, arm) == computed  # built and written
    assert _flatness(pr2.model, arm) == computed  # read
    assert len(list((cache.parent / "arm-slices").glob("*.arrays"))) == 1
    assert 0.35 < computed < 1.0  # the PR2's arm spreads in three directions


def test_working_direction_read_equals_computed(cache: Path) -> None:
    pr2 = load_description("pr2")
    assert pr2.model is not None
    arm = pr2.arms["left"]
    computed = _working_yaw(pr2.model, arm, None)
    for _ in range(2):  # a copy keeps nothing derived in memory: written, then read
        fresh = pickle.loads(pickle.dumps(pr2.model))
        assert working_yaw(fresh, arm) == computed == 0.0  # the PR2 works ahead
    assert len(list((cache.parent / "arm-directions").glob("*.arrays"))) == 1

"""The kitchen's drafted description is kept on disk: read back equal to a fresh draft,
keyed by every module the draft runs, and a damaged or foreign entry is drafted again.
A kept object's unpickler makes robocram's classes only."""

from __future__ import annotations

import cProfile
import gc
import pickle
from pathlib import Path

import numpy as np
import pytest

import robocram
from robocram.robots import disk_cache
from robocram.robots.kept_object import kept_object
from robocram.scenes.environment_description import EnvironmentDescription
from robocram.scenes.environment_draft import draft_environment
from robocram.scenes.kitchen_scene import DRAFTED_BY, KITCHEN, kitchen_description, kitchen_urdf

SRC = Path(robocram.__file__).resolve().parents[1]


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    return tmp_path


def _fresh() -> EnvironmentDescription:
    return draft_environment(kitchen_urdf(), name=KITCHEN).description


def test_the_kept_draft_equals_a_fresh_one(cache: Path) -> None:
    fresh = _fresh()
    kept = kitchen_description.__wrapped__()  # type: ignore[attr-defined]
    (entry,) = (cache / "environment-drafts").glob("*.arrays")
    read = kitchen_description.__wrapped__()  # type: ignore[attr-defined]
    assert read == kept and read.surfaces == fresh.surfaces and read.containers == fresh.containers
    assert read.stand_ins == fresh.stand_ins and len(read.surfaces) >= 5
    assert entry.stat().st_size > 0


def test_the_key_names_every_module_the_draft_runs() -> None:
    profile = cProfile.Profile()
    gc.collect()  # worlds earlier tests left would close inside the profile, not the draft
    gc.disable()
    try:
        profile.enable()
        _fresh()
        profile.disable()
    finally:
        gc.enable()
    profile.create_stats()
    ran = {
        ".".join(Path(file).resolve().relative_to(SRC).with_suffix("").parts)
        for file, _, _ in profile.stats  # type: ignore[attr-defined]
        if Path(file).is_file() and Path(file).resolve().is_relative_to(SRC / "robocram")
    }
    ran.discard("robocram.scenes.kitchen_scene")  # the caller, also in the key (its name)
    assert len(ran) > 5 and ran <= set(DRAFTED_BY), sorted(ran - set(DRAFTED_BY))


class _Counted:
    def __init__(self) -> None:
        self.count = 0

    def __call__(self) -> EnvironmentDescription:
        self.count += 1
        return EnvironmentDescription("box", Path("/nowhere/box.urdf"))


def _entry(cache: Path) -> Path:
    (entry,) = (cache / "test-objects").glob("*.arrays")
    return entry


def test_built_once_then_read(cache: Path) -> None:
    build = _Counted()
    first = kept_object("test-objects", "k", (), build, EnvironmentDescription)
    again = kept_object("test-objects", "k", (), build, EnvironmentDescription)
    assert first == again == build() and build.count == 2  # the third is the comparison's


@pytest.mark.parametrize("foreign", ["a function", "another type", "not a pickle"])
def test_a_foreign_entry_is_built_again_and_replaced(cache: Path, foreign: str) -> None:
    build = _Counted()
    kept_object("test-objects", "k", (), build, EnvironmentDescription)
    whole = _entry(cache).read_bytes()
    data = {
        "a function": pickle.dumps(print),  # a builtin's global: never made
        "another type": pickle.dumps(Path("/x")),  # made, but not an EnvironmentDescription
        "not a pickle": b"\x80\x05garbage",
    }[foreign]
    # a whole entry of the right key holding ``data``: the cache writes it for us
    arrays = {"pickle": np.frombuffer(data, dtype=np.uint8)}
    path = _entry(cache)
    path.unlink()
    disk_cache.kept_arrays("test-objects", "k", ("robocram.robots.kept_object",), lambda: arrays)
    assert _entry(cache).read_bytes() != whole
    value = kept_object("test-objects", "k", (), build, EnvironmentDescription)
    assert value == build() and build.count == 3
    assert _entry(cache).read_bytes() == whole  # replaced by a good entry

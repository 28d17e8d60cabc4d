"""A trace outlives the checkout that wrote it (issue 40).

A scene kept the kitchen's URDF by its absolute path only, so once that clone was removed
its traces could no longer be replayed or audited. A file inside robocram's package is now
kept relative to it too; an older store's path is re-rooted in the installed package; a
user's file that is gone is named, with the fix.
"""

from __future__ import annotations

import json
import sqlite3
from collections.abc import Callable
from contextlib import closing
from pathlib import Path

import pytest

from robocram.cli import main
from robocram.designators import a
from robocram.execution import perform
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.scenes.kitchen_scene import kitchen_urdf
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.errors import SceneFileMissing
from robocram.traces.trajectory_audit import audit_runs

TORSO = 0.1  # [m] the PR2's torso lift the run raises it to
OLD = "/gone/old-clone"  # a removed checkout


@pytest.fixture(scope="module")
def kitchen_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    db_path = tmp_path_factory.mktemp("kitchen") / "runs.db"
    scene = kitchen_scene("pr2")
    with trace_to(db_path, world=scene.world), simulated_robot(scene.world, "pr2"):
        perform(a.motion(type="moving-torso", joint_angle=TORSO))
    scene.world.close()
    return db_path


def _recipes(db_path: Path) -> list[dict[str, object]]:
    with closing(sqlite3.connect(db_path)) as db:
        (scene,) = db.execute("SELECT scene FROM runs").fetchone()
    return list(json.loads(scene))


def _rewritten(db_path: Path, tmp_path: Path, change: Callable[[dict[str, str]], None]) -> Path:
    """A copy of the store whose URDF bodies' file entries ``change`` rewrote."""
    copy = tmp_path / "copy.db"
    copy.write_bytes(db_path.read_bytes())
    with closing(sqlite3.connect(copy)) as db:  # closed: the write leaves the WAL
        recipes = _recipes(copy)
        for recipe in recipes:
            if "urdf" in recipe:
                change(recipe["urdf"])  # type: ignore[arg-type]
        db.execute("UPDATE runs SET scene = ?", (json.dumps(recipes),))
        db.commit()
    return copy


def _audited_whole(db_path: Path) -> None:
    with TraceDatabase(db_path, create=False) as db:
        report = audit_runs(db)
    assert report.clean, report.summary_lines()
    assert report.trajectories == 1 and report.configurations > 10  # the torso's, replayed


def test_the_kitchen_is_kept_relative_to_the_package(kitchen_run: Path) -> None:
    files = {r["name"]: r["urdf"] for r in _recipes(kitchen_run) if "urdf" in r}
    kitchen = files.pop("kitchen")
    assert isinstance(kitchen, dict)
    assert kitchen["package"] == "robocram/scenes/data/kitchen.urdf"
    assert Path(kitchen["path"]).resolve() == kitchen_urdf().resolve()
    packages = {e["package"].split("/")[0] for e in files.values() if isinstance(e, dict)}
    assert packages == {"robocram", "pybullet_data"}  # the things: the mug is pybullet's
    _audited_whole(kitchen_run)


def test_a_removed_checkout_s_trace_is_audited_from_the_installed_package(
    kitchen_run: Path, tmp_path: Path
) -> None:
    moved = _rewritten(kitchen_run, tmp_path, lambda e: e.update(path=OLD + e["path"]))
    _audited_whole(moved)


def test_an_older_store_s_path_is_rerooted_in_the_installed_package(
    kitchen_run: Path, tmp_path: Path
) -> None:
    """Stores written before the package entry have only the absolute path."""

    def older(entry: dict[str, str]) -> None:
        entry.pop("package")
        entry["path"] = OLD + entry["path"]

    _audited_whole(_rewritten(kitchen_run, tmp_path, older))


def test_a_user_s_file_that_is_gone_is_named_with_the_fix(
    kitchen_run: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    def own(entry: dict[str, str]) -> None:
        entry.pop("package")
        entry["path"] = str(tmp_path / f"my_{Path(entry['path']).name}")

    gone = _rewritten(kitchen_run, tmp_path, own)
    with TraceDatabase(gone, create=False) as db, pytest.raises(SceneFileMissing) as err:
        audit_runs(db)
    assert err.value.path == tmp_path / "my_kitchen.urdf"
    assert "my_kitchen.urdf" in str(err.value) and "put the file back" in str(err.value)
    assert main(["runs", "audit", str(gone)]) == 3  # bad input: one line, no traceback
    assert "my_kitchen.urdf" in capsys.readouterr().err

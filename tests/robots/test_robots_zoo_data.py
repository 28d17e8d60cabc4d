"""The public robots kept for the zoo (issue 37): each with its licence and source, small,
readable offline, and every box standing in for a missing mesh no longer than the robot.

The issue's UR arm without meshes got 4.9 to 7.75 m boxes from placeholder inertias; the
stand-ins are sized from the joints now (``robots/stand_in_size.py``).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from robocram.robots import RobotModel
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.stand_in_size import is_stand_in

ZOO = Path(__file__).resolve().parents[1] / "data" / "zoo"
KEPT = sorted(p.name for p in ZOO.iterdir() if p.is_dir())
MAX_FOLDER = 1_000_000  # [bytes] no multi-MB blobs


def test_the_zoo_keeps_at_least_six_public_robots() -> None:
    assert len(KEPT) >= 6


@pytest.mark.parametrize("name", KEPT)
def test_a_kept_robot_has_its_licence_and_source_and_stays_small(name: str) -> None:
    folder = ZOO / name
    assert (folder / "LICENSE").is_file() and (folder / "SOURCE.md").is_file()
    assert "github.com" in (folder / "SOURCE.md").read_text("utf-8")
    assert sum(f.stat().st_size for f in folder.rglob("*") if f.is_file()) < MAX_FOLDER


@pytest.mark.parametrize("name", KEPT)
def test_no_stand_in_box_is_longer_than_the_robot(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = RobotModel.from_file(ZOO / name / f"{name}.urdf", missing_packages_as_boxes=True)
    origins = np.array([pose.position for pose in link_poses(model).values()])
    span = float((origins.max(axis=0) - origins.min(axis=0)).max())
    boxes = [
        c.geometry.size
        for link in model.links.values()
        for c in link.collisions
        if is_stand_in(c.geometry)
    ]
    assert all(max(size) <= max(span, 0.08) + 1e-9 for size in boxes), (name, span)

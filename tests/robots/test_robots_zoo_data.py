"""The public robots kept for the zoo (issue 37): each with its licence and source, small,
readable offline, and every box standing in for a missing mesh no longer than the robot.

The issue's UR arm without meshes got 4.9 to 7.75 m boxes from placeholder inertias; the
stand-ins are sized from the joints now (``robots/stand_in_size.py``).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet as p
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


def test_a_torso_lowered_to_its_limit_stays_clear_of_the_column_box_below(
    tmp_path: Path,
) -> None:
    """Armar6's platform box reached the torso joint at zero (1.235 m up), 0.365 m above
    where the torso goes down to: lowered, the neck sat in it. Its box ends where the
    torso's travel comes nearest now; measured in a raw PyBullet, torso at its lower limit."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = RobotModel.from_file(ZOO / "armar6" / "armar6.urdf", missing_packages_as_boxes=True)
    path = tmp_path / "armar6.urdf"
    model.to_urdf(path)
    client = p.connect(p.DIRECT)
    try:
        body = p.loadURDF(str(path), useFixedBase=True, physicsClientId=client)
        infos = [
            p.getJointInfo(body, i, physicsClientId=client)
            for i in range(p.getNumJoints(body, physicsClientId=client))
        ]
        links = {info[12].decode(): info[0] for info in infos}
        torso = next(info[0] for info in infos if info[1] == b"torso_joint")
        assert infos[torso][8] == pytest.approx(-0.365)  # the lower limit
        p.resetJointState(body, torso, infos[torso][8], physicsClientId=client)
        gaps = {
            name: min(
                (
                    c[8]
                    for c in p.getClosestPoints(
                        body, body, 0.5, links["platform"], links[name], physicsClientId=client
                    )
                ),
                default=0.5,
            )
            for name in ("lower_neck", "middle_neck", "upper_neck")
        }
        assert min(gaps.values()) > 0.0, gaps
    finally:
        p.disconnect(client)

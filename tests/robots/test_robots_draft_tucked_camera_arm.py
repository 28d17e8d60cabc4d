"""A drafted mobile robot whose arm carries the camera parks it tucked over its base.

The Panda (example-robot-data; no camera link, so one is put on its wrist, and its base
is drafted as one that drives) parked its wrist 0.25 m ahead of its shoulder, its fingers
0.39 m ahead: at every stand near the kitchen's counter they were in the drawers. Drafted
now, no link past the shoulder's housing reaches past the base's front by more than a
link's girth. PyBullet judges, the URDF loaded bare with the drafted parking joints.
"""

from __future__ import annotations

from pathlib import Path

import pybullet
import pytest

from robocram.robots import draft_description, example_robot_data_folder

URDF = example_robot_data_folder() / "panda_description" / "urdf" / "panda.urdf"
GIRTH = 0.06  # [m] a link's mesh round its axis: the parked arm ends this far past the base
SHOULDER_HOUSING = "panda_link1"  # turns about the vertical over the base: as it is


def _reach_ahead(urdf: Path, joints: dict[str, float]) -> tuple[float, float]:
    """[m] the base's front and the farthest front of the arm's links past the shoulder's
    housing, the base at the origin looking along x, the joints set."""
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(urdf), useFixedBase=True, physicsClientId=client)
        count = pybullet.getNumJoints(body, physicsClientId=client)
        info = [pybullet.getJointInfo(body, i, physicsClientId=client) for i in range(count)]
        for i, row in enumerate(info):
            if row[1].decode() in joints:
                pybullet.resetJointState(body, i, joints[row[1].decode()], physicsClientId=client)
        base = pybullet.getAABB(body, -1, physicsClientId=client)[1][0]
        links = [i for i, row in enumerate(info) if row[12].decode() != SHOULDER_HOUSING]
        ahead = max(pybullet.getAABB(body, i, physicsClientId=client)[1][0] for i in links)
        return float(base), float(ahead)
    finally:
        pybullet.disconnect(client)


def test_a_mobile_robots_camera_arm_parks_over_its_base_not_ahead_of_it() -> None:
    if not URDF.is_file():
        pytest.skip("example-robot-data is not installed")
    desc = draft_description(URDF).description
    assert desc.drive != "fixed"
    (arm,) = desc.arms.values()
    assert desc.cameras[0].frame.startswith(arm.end_effector_link)  # the arm carries it
    base, ahead = _reach_ahead(URDF, dict(arm.parking))
    assert ahead <= base + GIRTH  # 0.39 m ahead of the base's origin before, 0.10 m now

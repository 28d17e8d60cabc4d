"""A fixed robot whose head camera cannot see its arms' reach is drafted with its wrist camera.

Baxter's head only pans: its camera sees 33 degrees down at most, and at the right
shoulder's height no nearer than 1.12 m from it, beyond 0.85 of its 1.14 m reach. Its
right arm (the one the scenes pick with) carries ``right_hand_camera_link``, named like a
camera: the draft takes it, by its own axes (its z along the hand), and parks the arm to
look. Raw PyBullet judges the head camera: its lowest view ray, at zero joints.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pybullet

from robocram.robots import example_robot_data_folder
from tests.drafts import drafted

BAXTER = example_robot_data_folder() / "baxter_description/urdf/baxter.urdf"
TRACY = Path(__file__).resolve().parents[1] / "data" / "zoo" / "tracy" / "tracy.urdf"
REACH = 1.14  # [m] Baxter's right arm, shoulder to wrist, stretched (zoo23)
HALF_VIEW = math.radians(45.0) / 2  # the draft's vertical field, halved (no sensor given)


def _link(body: int, client: int, name: str) -> int:
    count = pybullet.getNumJoints(body, physicsClientId=client)
    return next(
        i
        for i in range(count)
        if pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode() == name
    )


def test_baxters_head_camera_sees_beyond_its_reach_raw() -> None:
    """The premise, on raw PyBullet: the lowest ray of the head camera's view meets the
    right shoulder's height beyond 0.85 of the arm's reach from it."""
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(BAXTER), useFixedBase=True, physicsClientId=client)
        camera = pybullet.getLinkState(body, _link(body, client, "head_camera_link"),
                                       physicsClientId=client)  # fmt: skip
        shoulder = pybullet.getLinkState(body, _link(body, client, "right_upper_shoulder"),
                                         physicsClientId=client)[4]  # fmt: skip
        axes = np.asarray(pybullet.getMatrixFromQuaternion(camera[5])).reshape(3, 3)
        z = axes[:, 2]
        down = math.asin(-z[2]) + HALF_VIEW
        ahead = (camera[4][2] - shoulder[2]) / math.tan(down)
        heading = z[:2] / np.linalg.norm(z[:2])
        seen = np.asarray(camera[4][:2]) + ahead * heading
        assert float(np.linalg.norm(seen - np.asarray(shoulder[:2]))) > 0.85 * REACH
    finally:
        pybullet.disconnect(client)


def test_baxter_is_drafted_with_its_right_wrist_camera_by_its_own_axes() -> None:
    draft = drafted(BAXTER)
    desc = draft.description
    assert desc.base_type == "fixed"
    assert desc.cameras[0].frame == "right_hand_camera_link"
    assert not any(f.parent == "right_hand_camera_link" for f in desc.extra_frames)
    assert "head_camera_link cannot tilt" in draft.why["cameras.0"]
    assert "it carries the camera" in draft.why["arms.right.parking"]


def test_a_fixed_camera_that_sees_its_table_is_kept() -> None:
    """Tracy's camera looks 72 degrees down onto its own top: it sees its arms' reach."""
    assert "camera" in drafted(TRACY).description.cameras[0].frame
    assert "cannot tilt" not in drafted(TRACY).why["cameras.0"]

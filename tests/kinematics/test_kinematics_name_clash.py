"""A joint named like a link: the SO-100's ``gripper`` joint turns its ``jaw`` below the
``gripper`` link. Pinocchio's chain reduction made the locked joint a frame of the same
name as the link and failed ("Several frames match"); IK on its arm now solves, judged by
PyBullet's own forward kinematics of the URDF the model writes."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.kinematics import solve_ik
from robocram.robots import example_robot_data_folder, load_description
from robocram.tf import Pose
from tests.drafts import drafted

SO100 = example_robot_data_folder() / "so_arm_description" / "urdf" / "so100.urdf"
GOAL = {"shoulder_pan": 0.3, "shoulder_lift": 0.4, "elbow_flex": -0.6, "wrist_flex": 0.5,
        "wrist_roll": 0.2}  # fmt: skip


def test_ik_solves_on_an_arm_whose_gripper_joint_is_named_like_its_link(tmp_path: Path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        desc = load_description(drafted(SO100).description)
    model = desc.model
    assert "gripper" in model.links and "gripper" in model.joints  # the clash
    tool = desc.arms["arm"].tool_frame
    client = pybullet.connect(pybullet.DIRECT)
    try:
        model.to_urdf(tmp_path / "so100.urdf")
        body = pybullet.loadURDF(str(tmp_path / "so100.urdf"), physicsClientId=client)
        index = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[1].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }
        link = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }

        def tool_at(values: dict[str, float]) -> tuple[np.ndarray, np.ndarray]:
            for name, value in values.items():
                pybullet.resetJointState(body, index[name], value, physicsClientId=client)
            state = pybullet.getLinkState(
                body, link[tool], computeForwardKinematics=True, physicsClientId=client
            )
            return np.asarray(state[4]), np.asarray(state[5])

        position, orientation = tool_at(GOAL)
        target = Pose(tuple(position), tuple(orientation))
        result = solve_ik(desc, "arm", target, seed={j: 0.0 for j in GOAL})
        assert result.success
        reached, _ = tool_at(dict(result.joint_positions))
        assert reached == pytest.approx(position, abs=2e-3)
    finally:
        pybullet.disconnect(client)

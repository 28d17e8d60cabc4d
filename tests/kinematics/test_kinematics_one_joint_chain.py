"""IK on a chain of one joint: the smallest arm still gets an answer or a clean failure."""

from __future__ import annotations

import dataclasses
import warnings

import pytest

from robocram.kinematics import IKOptions, forward_kinematics, solve_ik
from robocram.robots import (
    ArmDescription,
    FrameSpec,
    RobotDescription,
    example_robot_data_folder,
    load_description,
)
from robocram.robots.loading import LoadedDescription
from robocram.tf import Pose

URDF = example_robot_data_folder() / "panda_description/urdf/panda.urdf"
TOOL_IN_FLANGE = Pose((0.0, 0.0, 0.1), (0.0, -0.7071068, 0.0, 0.7071068))  # x along the flange's z


@pytest.fixture(scope="module")
def wrist_only() -> LoadedDescription:
    """The panda with an 'arm' of its last joint alone (link6 to link7)."""
    arm = ArmDescription(
        name="arm",
        end_effector_link="panda_link7",
        tool_frame="wrist_tool",
        base_link="panda_link6",
    )
    desc = RobotDescription(
        name="panda_wrist",
        urdf=URDF,
        base_frame="panda_link0",
        arms={"arm": arm},
        extra_frames=(FrameSpec("wrist_tool", "panda_link8", TOOL_IN_FLANGE),),
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_description(desc)


def test_the_chain_has_one_joint(wrist_only: LoadedDescription) -> None:
    assert wrist_only.arms["arm"].joints == ("panda_joint7",)


def test_a_reachable_turn_is_found_to_the_tolerance(wrist_only: LoadedDescription) -> None:
    target = forward_kinematics(wrist_only, {"panda_joint7": 0.3}, "wrist_tool")
    result = solve_ik(wrist_only, "arm", target)
    assert result.success
    assert result.joint_positions["panda_joint7"] == pytest.approx(0.3, abs=1e-3)


def test_a_pose_off_the_circle_fails_cleanly(wrist_only: LoadedDescription) -> None:
    here = forward_kinematics(wrist_only, {}, "wrist_tool")
    off = dataclasses.replace(here, position=(here.position[0] + 0.1, *here.position[1:]))
    result = solve_ik(
        wrist_only, "arm", Pose(off.position, off.orientation), options=IKOptions(max_restarts=5)
    )
    assert not result.success
    assert result.position_error > 0.05

"""The report card of ``robocram robot check``: built-in robots pass, broken ones are named.

A PR2 description broken three ways (a tool frame turned backwards, a camera frame facing
backwards, a parking value out of limits) gets a card that names each fault and its fix.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import pytest

from robocram.cli import main
from robocram.robot_check import RobotCheckError, check_robot, description_from
from robocram.robots import FrameSpec, RobotDescription
from robocram.robots.builtin import builtin_description
from robocram.tf import Pose

EXIT_OK, EXIT_FAILED, EXIT_INPUT = 0, 1, 3


def _broken_pr2() -> RobotDescription:
    pr2 = builtin_description("pr2")
    backwards_tool = FrameSpec(
        "r_backwards_tool_frame",
        "r_gripper_tool_frame",
        Pose.from_xyz_rpy((0, 0, 0), (0, 0, math.pi)),
    )
    backwards_camera = FrameSpec(
        "backwards_optical_frame",
        "wide_stereo_optical_frame",
        Pose.from_xyz_rpy((0, 0, 0), (0, math.pi, 0)),
    )
    left = pr2.arms["left"]
    parking = {**left.parking, "l_elbow_flex_joint": 1.0}  # the elbow bends to [-2.32, 0]
    arms = {
        "left": replace(left, parking=parking),
        "right": replace(pr2.arms["right"], tool_frame="r_backwards_tool_frame"),
    }
    cameras = (replace(pr2.cameras[0], frame="backwards_optical_frame"),)
    return replace(pr2, arms=arms, cameras=cameras, extra_frames=(backwards_tool, backwards_camera))


def test_card_names_each_fault_of_a_broken_description() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(_broken_pr2())
    assert not card.passed
    failed = {r.name: r for r in card.failures()}
    assert len(failed) == 3, card.render()
    parking = failed["arms['left'].parking: l_elbow_flex_joint"]
    assert "1.0 is outside the limits" in parking.detail and "within" in parking.fix
    tool = failed["description: arms['right'].tool_frame"]
    assert "r_backwards_tool_frame" in tool.detail
    camera = failed["description: cameras[0].frame"]
    assert "backwards_optical_frame" in camera.detail and "optical frame" in camera.fix
    assert "FAIL description: arms['right'].tool_frame" in card.render()


def test_card_drives_what_the_checker_cannot_see() -> None:
    """A tool frame 10 cm beside the fingers passes the checker; the grip finds it."""
    pr2 = builtin_description("pr2")
    aside = FrameSpec("r_aside_tool_frame", "r_gripper_tool_frame", Pose((0.0, 0.0, 0.1)))
    arms = {"right": replace(pr2.arms["right"], tool_frame="r_aside_tool_frame")}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(replace(pr2, arms=arms, extra_frames=(aside,)))
    assert [r.name for r in card.failures()] == ["right arm: grip"], card.render()
    assert "between the fingertips" in card.result("right arm: grip").fix
    assert card.result("right arm: reach").passed


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_builtin_robots_pass_every_check(robot: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(description_from(robot))
    assert card.passed, card.render()
    names = {r.name for r in card.results}
    assert {"torso", "look", "detect"} <= names
    arm = next(iter(builtin_description(robot).arms))
    assert {f"{arm} arm: reach", f"{arm} arm: grip", f"{arm} arm: gripper"} <= names


def test_cli_check_exit_codes(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robot", "check", "robocram.robots.builtin.hsrb:description"]) == EXIT_OK
    assert "all checks pass" in capsys.readouterr().out
    assert main(["robot", "check", "no_such_robot"]) == EXIT_INPUT
    assert "no built-in robot" in capsys.readouterr().err


def test_description_from_names_what_it_needs(tmp_path: object) -> None:
    with pytest.raises(RobotCheckError, match="no file"):
        description_from("missing_file.py")
    with pytest.raises(RobotCheckError, match="not a RobotDescription"):
        description_from("robocram.robots.builtin.hsrb:URDF")

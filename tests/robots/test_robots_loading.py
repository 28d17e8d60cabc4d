"""load_description: built-in robots load and check; typos fail with helpful errors."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest

from robocram.robots import (
    ArmDescription,
    DescriptionCheckError,
    DescriptionError,
    FrameSpec,
    JointValueError,
    RobotDescription,
    load_description,
)
from robocram.robots.builtin import builtin_description, builtin_names
from robocram.tf import Pose

PR2_RIGHT_JOINTS = (
    "r_shoulder_pan_joint",
    "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint",
    "r_elbow_flex_joint",
    "r_forearm_roll_joint",
    "r_wrist_flex_joint",
    "r_wrist_roll_joint",
)


@pytest.fixture(scope="module")
def pr2() -> RobotDescription:
    return load_description("pr2")


def test_pr2_loads_with_its_arms_head_and_camera(pr2: RobotDescription) -> None:
    model = pr2.model
    assert model is not None and model.name == "pr2"
    assert set(pr2.arms) == {"left", "right"}
    right = pr2.arms["right"]
    assert right.joints == PR2_RIGHT_JOINTS
    assert right.links[0] == "r_shoulder_pan_link" and right.links[-1] == "r_wrist_roll_link"
    assert right.tool_frame == "r_gripper_tool_frame"
    torso = model.joints["torso_lift_joint"]
    assert (torso.type, torso.lower, torso.upper) == ("prismatic", 0.0, pytest.approx(0.31))
    camera = pr2.cameras[0]
    assert camera.frame in model.links
    assert camera.horizontal_fov == pytest.approx(math.pi / 2)
    assert pr2.pan_tilt is not None and pr2.pan_tilt.pan_joint == "head_pan_joint"
    for arm in pr2.arms.values():
        for joint, value in {**arm.parking, **arm.carrying}.items():
            j = model.joints[joint]
            assert j.lower is not None and j.upper is not None
            assert j.lower <= value <= j.upper


def test_pr2_camera_height_range_matches_the_torso_travel(pr2: RobotDescription) -> None:
    assert pr2.model is not None
    chain = pr2.model.chain(pr2.base_frame, pr2.cameras[0].frame)
    camera_in_base = Pose()
    for joint in chain:
        camera_in_base = camera_in_base * joint.origin
    camera = pr2.cameras[0]
    assert camera.minimal_height == pytest.approx(camera_in_base.position[2], abs=0.01)
    travel = pr2.model.joints["torso_lift_joint"].upper or 0.0
    assert camera.maximal_height - camera.minimal_height == pytest.approx(travel, abs=0.01)


def test_quadrotor_loads_flying_and_armless() -> None:
    quad = load_description("hector_quadrotor")
    assert quad.name == "quadrotor" and quad.flying and quad.arms == {}
    assert quad.model is not None and quad.model.root_link == quad.base_frame == "base_link"
    mesh = quad.model.links["base_link"].visuals[0].geometry
    assert mesh.kind == "mesh" and Path(mesh.filename).is_file()


def test_builtin_registry_names_and_unknown_robot() -> None:
    assert {"pr2", "hsrb", "hsr", "boxy", "quadrotor", "hector_quadrotor"} <= set(builtin_names())
    with pytest.raises(DescriptionError, match="no built-in robot 'pr3'.*did you mean 'pr2'"):
        builtin_description("pr3")


def test_typo_in_arm_joint_names_the_joint_and_the_fix() -> None:
    desc = builtin_description("pr2")
    right = replace(desc.arms["right"], joints=("r_shoulder_pan", *PR2_RIGHT_JOINTS[1:]))
    with pytest.raises(DescriptionCheckError) as info:
        load_description(replace(desc, arms={**desc.arms, "right": right}))
    (problem,) = info.value.problems
    assert (problem.kind, problem.name) == ("joint", "r_shoulder_pan")
    assert problem.suggestions[0] == "r_shoulder_pan_joint"
    assert "joint 'r_shoulder_pan' (in arms['right'].joints) not in pr2.urdf" in str(info.value)
    assert "did you mean 'r_shoulder_pan_joint'" in str(info.value)


def test_all_problems_are_reported_together() -> None:
    desc = replace(builtin_description("pr2"), torso_joint="torso_lift", base_frame="base_fotprint")
    with pytest.raises(DescriptionCheckError) as info:
        load_description(desc)
    names = {p.name: p.suggestions for p in info.value.problems}
    assert names["torso_lift"][0] == "torso_lift_joint"
    assert names["base_fotprint"][0] == "base_footprint"


def test_fixed_joint_named_as_arm_joint_is_rejected() -> None:
    desc = builtin_description("pr2")
    right = replace(desc.arms["right"], joints=("r_gripper_palm_joint",))
    with pytest.raises(
        DescriptionCheckError, match=r"movable joint \(fixed\) 'r_gripper_palm_joint'"
    ):
        load_description(replace(desc, arms={"right": right}))


def test_out_of_limit_parking_value_fails() -> None:
    desc = builtin_description("pr2")
    right = replace(desc.arms["right"], parking={"r_elbow_flex_joint": 0.5})
    with pytest.raises(JointValueError, match="r_elbow_flex_joint") as info:
        load_description(replace(desc, arms={"right": right}))
    assert (info.value.lower, info.value.upper) == pytest.approx((-2.3213, 0.0))


def test_arm_inferred_from_base_and_tip_with_a_tool_frame_added_in_code() -> None:
    base = builtin_description("pr2")
    arm = ArmDescription(
        name="left",
        end_effector_link="l_wrist_roll_link",
        tool_frame="l_pointer_tip",
        base_link="torso_lift_link",
    )
    tip = FrameSpec("l_pointer_tip", "l_wrist_roll_link", Pose((0.3, 0.0, 0.0)))
    desc = replace(base, arms={"left": arm}, extra_frames=(tip,))
    loaded = load_description(desc)
    assert loaded.arms["left"].joints == tuple(j.replace("r_", "l_", 1) for j in PR2_RIGHT_JOINTS)
    assert loaded.model is not None
    assert loaded.model.joints["l_pointer_tip_joint"].parent == "l_wrist_roll_link"
    again = load_description(loaded)  # loading a loaded description keeps it as is
    assert again.arms == loaded.arms and "l_pointer_tip" in (again.model or loaded.model).links


def test_arm_without_joints_or_base_link_says_what_to_give() -> None:
    base = builtin_description("pr2")
    arm = ArmDescription(
        name="left", end_effector_link="l_wrist_roll_link", tool_frame="l_wrist_roll_link"
    )
    with pytest.raises(DescriptionCheckError, match="give joints or a base_link"):
        load_description(replace(base, arms={"left": arm}))


def test_not_a_description_is_a_type_error() -> None:
    with pytest.raises(TypeError, match="robot name, a description file or a RobotDescription"):
        load_description(42)  # type: ignore[arg-type]


def test_a_description_file_may_be_a_path() -> None:
    stretch = Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py"
    assert load_description(stretch).name == load_description(str(stretch)).name


def test_loading_gives_a_loaded_description_whose_model_is_set() -> None:
    from robocram.robots import LoadedDescription

    spec = builtin_description("pr2")
    assert not isinstance(spec, LoadedDescription) and spec.model is None
    loaded = load_description(spec)
    assert isinstance(loaded, LoadedDescription)
    assert loaded.model.root_link == "base_footprint"
    assert loaded.arms["left"].joints[0] == "l_shoulder_pan_joint"
    again = load_description(replace(loaded, name="pr2-copy"))
    assert isinstance(again, LoadedDescription) and again.model is loaded.model


def test_sides_name_the_arms_of_two_armed_robots_whatever_they_are_called() -> None:
    pr2 = builtin_description("pr2")
    port = replace(pr2.arms["left"], name="port", side="left")
    desc = replace(pr2, arms={"port": port, "right": pr2.arms["right"]})
    assert desc.arm_called("left") == "port" and desc.arm_called("port") == "port"
    assert desc.arm_called("right") == "right" and desc.arm_called("lefty") == "lefty"
    assert desc.resources() == ("navigation", "torso", "perception", "ptu", "grippers", "arms")
    assert load_description("quadrotor").resources() == ("flying", "distance_sensor")

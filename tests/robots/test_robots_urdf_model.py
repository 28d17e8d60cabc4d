"""RobotModel: parsing, tree queries, frames and boxes in code, writing URDF for PyBullet."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.robots import (
    BoxSpec,
    DescriptionError,
    FrameSpec,
    MissingMeshWarning,
    RobotModel,
    UrdfError,
)
from robocram.tf import Pose


def test_parses_joints_links_and_limits(tiny_package: Path) -> None:
    model = RobotModel.from_file(tiny_package / "tiny_pkg" / "urdf" / "tiny.urdf")
    assert model.name == "tiny"
    assert model.root_link == "base"
    arm = model.joints["arm_joint"]
    assert (arm.type, arm.parent, arm.child, arm.axis) == ("revolute", "base", "arm", (0, 0, 1))
    assert (arm.lower, arm.upper, arm.velocity, arm.effort) == (-1.0, 2.0, 1.5, 10.0)
    assert arm.origin.position == pytest.approx((0, 0, 0.5))
    assert arm.origin.rpy()[2] == pytest.approx(math.pi / 2)
    mimic = model.joints["finger_b_joint"].mimic
    assert mimic is not None and (mimic.joint, mimic.multiplier) == ("finger_a_joint", -1.0)
    assert [j.name for j in model.movable_joints()] == [
        "arm_joint",
        "finger_a_joint",
        "finger_b_joint",
    ]
    mesh = model.links["base"].visuals[0].geometry
    assert mesh.kind == "mesh"
    assert mesh.filename == str(tiny_package / "tiny_pkg" / "meshes" / "body.stl")


def test_chain_runs_base_to_tip_and_rejects_unrelated_links(tiny_package: Path) -> None:
    model = RobotModel.from_file(tiny_package / "tiny_pkg" / "urdf" / "tiny.urdf")
    assert [j.name for j in model.chain("base", "finger_a")] == ["arm_joint", "finger_a_joint"]
    assert model.chain("arm", "arm") == []
    with pytest.raises(DescriptionError, match="does not hang below"):
        model.chain("finger_a", "finger_b")
    with pytest.raises(DescriptionError, match="did you mean 'finger_a'"):
        model.chain("base", "finger_aa")


def test_continuous_and_fixed_joint_limits() -> None:
    xml = """<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
      <joint name="spin" type="continuous"><parent link="a"/><child link="b"/></joint>
      <joint name="glue" type="fixed"><parent link="b"/><child link="c"/></joint></robot>"""
    model = RobotModel.from_string(xml)
    assert (model.joints["spin"].lower, model.joints["spin"].upper) == (-math.inf, math.inf)
    assert (model.joints["glue"].lower, model.joints["glue"].upper) == (None, None)


def test_malformed_xml_names_file_and_line(tmp_path: Path) -> None:
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n  <link name="a">\n</robot>\n')
    with pytest.raises(UrdfError, match=r"bad\.urdf:3: not well-formed XML") as info:
        RobotModel.from_file(bad)
    assert info.value.line == 3


def test_doctype_with_entity_is_refused() -> None:
    xml = (
        '<?xml version="1.0"?>\n<!DOCTYPE r [<!ENTITY lol "lol">]>\n'
        '<robot name="&lol;"><link name="a"/></robot>'
    )
    with pytest.raises(UrdfError, match="DOCTYPE/ENTITY declarations are refused"):
        RobotModel.from_string(xml)


def test_joint_with_missing_link_names_it_and_suggests() -> None:
    xml = """<robot name="r"><link name="base_link"/><link name="arm_link"/>
      <joint name="j" type="fixed"><parent link="base_link"/><child link="arm_lnk"/></joint>
      </robot>"""
    with pytest.raises(
        UrdfError, match=r"<string>:2: joint 'j' has child link 'arm_lnk'.*'arm_link'"
    ):
        RobotModel.from_string(xml)


def test_two_roots_and_unknown_joint_type_are_errors() -> None:
    with pytest.raises(UrdfError, match="exactly one root link"):
        RobotModel.from_string('<robot name="r"><link name="a"/><link name="b"/></robot>')
    xml = """<robot name="r"><link name="a"/><link name="b"/>
      <joint name="j" type="hinge"><parent link="a"/><child link="b"/></joint></robot>"""
    with pytest.raises(UrdfError, match="unknown type 'hinge'"):
        RobotModel.from_string(xml)


def test_missing_mesh_becomes_a_box_spanning_its_joints_with_one_warning(
    tiny_package: Path,
) -> None:
    """Issue 37: sized from the kinematics (the base reaches the arm's joint 0.5 m up),
    never from the inertia (its solid box would be sqrt(0.3) = 0.55 m each way)."""
    (tiny_package / "tiny_pkg" / "meshes" / "body.stl").unlink()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = RobotModel.from_file(tiny_package / "tiny_pkg" / "urdf" / "tiny.urdf")
    mesh_warnings = [w for w in caught if issubclass(w.category, MissingMeshWarning)]
    assert len(mesh_warnings) == 1
    assert "body.stl" in str(mesh_warnings[0].message)
    visual = model.links["base"].visuals[0]
    box = visual.geometry
    assert box.kind == "box" and box.filename.endswith("body.stl")  # marked as a stand-in
    arm = model.joints["arm_joint"].origin.position[2]
    assert box.size[0] == box.size[1] == pytest.approx(0.08)  # as thick as allowed
    assert arm <= box.size[2] <= arm + 0.08
    assert visual.origin.position == pytest.approx((0.0, 0.0, arm / 2))
    assert box.size != pytest.approx((math.sqrt(0.3),) * 3)


def test_frames_and_boxes_added_in_code_reach_pybullet(tiny_package: Path, tmp_path: Path) -> None:
    model = RobotModel.from_file(tiny_package / "tiny_pkg" / "urdf" / "tiny.urdf")
    tool = FrameSpec("tool_frame", "arm", Pose((0.0, 0.0, 0.25)))
    box = BoxSpec("bumper", "base", Pose((0.3, 0.0, 0.0)), (0.1, 0.4, 0.05))
    extended = model.with_frame(tool).with_box(box)
    assert "tool_frame" not in model.links  # the original is untouched
    assert extended.joints["tool_frame_joint"].parent == "arm"
    assert extended.links["bumper"].collisions[0].geometry.size == (0.1, 0.4, 0.05)
    text = extended.to_urdf(tmp_path / "out.urdf")
    assert '<link name="tool_frame"' in text and 'size="0.1 0.4 0.05"' in text
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(tmp_path / "out.urdf"), physicsClientId=client)
        links = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }
        assert {"arm", "finger_a", "finger_b", "tool_frame", "bumper"} <= set(links)
        state = pybullet.getLinkState(body, links["tool_frame"], physicsClientId=client)
        assert state[4] == pytest.approx((0.0, 0.0, 0.75), abs=1e-6)
        info = pybullet.getJointInfo(body, links["arm"], physicsClientId=client)
        assert (info[8], info[9]) == pytest.approx((-1.0, 2.0))
    finally:
        pybullet.disconnect(client)


def test_adding_an_existing_or_misparented_frame_fails(tiny_package: Path) -> None:
    urdf = tiny_package / "tiny_pkg" / "urdf"
    model = RobotModel.from_string((urdf / "tiny.urdf").read_text(), urdf, [tiny_package])
    with pytest.raises(DescriptionError, match="a link of that name exists"):
        model.with_frame(FrameSpec("arm", "base", Pose()))
    with pytest.raises(DescriptionError, match="link 'amr' not in .*did you mean 'arm'"):
        model.with_frame(FrameSpec("tcp", "amr", Pose()))
    with pytest.raises(DescriptionError, match="positive sizes"):
        model.with_box(BoxSpec("flat", "arm", Pose(), (0.1, 0.0, 0.1)))


def test_round_trip_keeps_the_model(tiny_package: Path) -> None:
    model = RobotModel.from_file(tiny_package / "tiny_pkg" / "urdf" / "tiny.urdf")
    again = RobotModel.from_string(model.to_urdf())
    assert again.joints == model.joints
    assert again.links == model.links


def test_named_materials_give_visual_colours() -> None:
    xml = """<robot name="r"><material name="Red"><color rgba="1 0 0 1"/></material>
      <link name="a"><visual><geometry><sphere radius="0.1"/></geometry>
      <material name="Red"/></visual></link></robot>"""
    visual = RobotModel.from_string(xml).links["a"].visuals[0]
    assert (visual.material, visual.rgba) == ("Red", (1.0, 0.0, 0.0, 1.0))
    assert 'rgba="1.0 0.0 0.0 1.0"' in RobotModel.from_string(xml).to_urdf()

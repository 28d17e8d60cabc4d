"""Folding fixed links into their parents keeps shapes, mass, inertia and frames."""

from __future__ import annotations

import numpy as np
import pytest

from robocram.robots import RobotModel, merge_fixed_links
from robocram.tf import Pose

ARM = """<robot name="arm">
  <link name="base"><inertial><mass value="2"/><origin xyz="0 0 0"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <link name="plate"><inertial><mass value="2"/><origin xyz="0 0 0"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="sensor"/>
  <link name="upper"/>
  <joint name="plate_joint" type="fixed"><parent link="base"/><child link="plate"/>
    <origin xyz="1 0 0"/></joint>
  <joint name="sensor_joint" type="fixed"><parent link="plate"/><child link="sensor"/>
    <origin xyz="0 0 0.5" rpy="0 0 1.5707963267948966"/></joint>
  <joint name="shoulder" type="revolute"><parent link="sensor"/><child link="upper"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1"/></joint>
</robot>"""


def test_fixed_links_fold_into_the_first_movable_ancestor() -> None:
    merged = merge_fixed_links(RobotModel.from_string(ARM))
    model = merged.model
    assert set(model.links) == {"base", "upper"} and list(model.joints) == ["shoulder"]
    assert merged.frames["plate"][0] == "base" and merged.frames["sensor"][0] == "base"
    assert merged.frames["sensor"][1].position == pytest.approx((1.0, 0.0, 0.5))
    shoulder = model.joints["shoulder"]
    assert shoulder.parent == "base"
    expected = Pose.from_xyz_rpy((1.0, 0.0, 0.5), (0, 0, np.pi / 2)) * Pose((0.2, 0.0, 0.0))
    assert np.allclose(shoulder.origin.matrix(), expected.matrix(), atol=1e-12)
    [box] = model.links["base"].collisions
    assert box.origin.position == pytest.approx((1.0, 0.0, 0.0))


def test_mass_and_inertia_combine_about_the_common_centre() -> None:
    inertial = merge_fixed_links(RobotModel.from_string(ARM)).model.links["base"].inertial
    assert inertial is not None and inertial.mass == pytest.approx(4.0)
    assert inertial.origin.position == pytest.approx((0.5, 0.0, 0.0))
    ixx, ixy, ixz, iyy, iyz, izz = inertial.inertia
    # two 2 kg bodies 0.5 m either side of the centre along x: + 2 * 2 * 0.5^2 about y, z
    assert (ixx, iyy, izz) == pytest.approx((0.2, 0.2 + 1.0, 0.2 + 1.0))
    assert (ixy, ixz, iyz) == pytest.approx((0.0, 0.0, 0.0))


def test_kept_links_are_not_folded() -> None:
    merged = merge_fixed_links(RobotModel.from_string(ARM), keep=frozenset({"sensor"}))
    assert set(merged.model.links) == {"base", "sensor", "upper"}
    assert merged.model.joints["sensor_joint"].parent == "base"
    assert merged.model.joints["shoulder"].parent == "sensor"

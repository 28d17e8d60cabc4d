"""Shared fixtures of the robots tests: a tiny two-link URDF and a package folder for it."""

from __future__ import annotations

from pathlib import Path

import pytest

TINY_URDF = """<?xml version="1.0"?>
<robot name="tiny">
  <link name="base">
    <inertial><mass value="2.0"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <visual><geometry><mesh filename="package://tiny_pkg/meshes/body.stl"/></geometry></visual>
  </link>
  <link name="arm">
    <collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>
  </link>
  <link name="finger_a"/>
  <link name="finger_b"/>
  <joint name="arm_joint" type="revolute">
    <origin xyz="0 0 0.5" rpy="0 0 1.5707963267948966"/>
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1.0" upper="2.0" velocity="1.5" effort="10"/>
  </joint>
  <joint name="finger_a_joint" type="prismatic">
    <parent link="arm"/><child link="finger_a"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.04" velocity="0.1" effort="5"/>
  </joint>
  <joint name="finger_b_joint" type="prismatic">
    <parent link="arm"/><child link="finger_b"/><axis xyz="0 1 0"/>
    <limit lower="-0.04" upper="0" velocity="0.1" effort="5"/>
    <mimic joint="finger_a_joint" multiplier="-1" offset="0"/>
  </joint>
</robot>
"""

# An ASCII STL tetrahedron: enough for PyBullet to load the visual.
TINY_STL = """solid t
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0.1 0 0
vertex 0 0.1 0
endloop
endfacet
endsolid t
"""


@pytest.fixture
def tiny_package(tmp_path: Path) -> Path:
    """A folder ``<tmp>/ws`` holding package ``tiny_pkg`` with a URDF and its mesh."""
    package = tmp_path / "ws" / "tiny_pkg"
    (package / "meshes").mkdir(parents=True)
    (package / "urdf").mkdir()
    (package / "meshes" / "body.stl").write_text(TINY_STL)
    (package / "urdf" / "tiny.urdf").write_text(TINY_URDF)
    return tmp_path / "ws"

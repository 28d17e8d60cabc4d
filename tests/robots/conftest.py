"""Shared fixtures of the robots tests: a tiny two-link URDF and a package folder for it."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from pathlib import Path

import numpy as np
import pybullet as p
import pytest

from robocram.robots import RobotDescription

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


class Sim:
    """The model in a headless PyBullet, with joints and links by name."""

    def __init__(self, urdf: Path) -> None:
        self.client = p.connect(p.DIRECT)
        self.body = p.loadURDF(str(urdf), useFixedBase=True, physicsClientId=self.client)
        infos = [
            p.getJointInfo(self.body, i, physicsClientId=self.client)
            for i in range(p.getNumJoints(self.body, physicsClientId=self.client))
        ]
        self.joints = {info[1].decode(): info[0] for info in infos}
        self.links = {info[12].decode(): info[0] for info in infos}

    def set(self, values: Mapping[str, float]) -> None:
        """Set ``values``; every other joint goes to 0."""
        for name, index in self.joints.items():
            value = values.get(name, 0.0)
            p.resetJointState(self.body, index, value, physicsClientId=self.client)

    def frame(self, link: str) -> tuple[np.ndarray, np.ndarray]:
        """Position [m] and rotation matrix of ``link`` in the world (= base_footprint)."""
        state = p.getLinkState(
            self.body, self.links[link], computeForwardKinematics=True, physicsClientId=self.client
        )
        rotation = np.array(p.getMatrixFromQuaternion(state[5])).reshape(3, 3)
        return np.array(state[4]), rotation


@pytest.fixture(scope="module")
def robot_in_pybullet(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Sim]:
    """The module's ``robot`` description, written by ``to_urdf`` and loaded in PyBullet."""
    desc: RobotDescription = request.getfixturevalue("robot")
    assert desc.model is not None
    path = tmp_path_factory.mktemp(desc.name) / f"{desc.name}.urdf"
    desc.model.to_urdf(path)
    sim = Sim(path)
    yield sim
    p.disconnect(sim.client)

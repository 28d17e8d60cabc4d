"""``<capsule>`` collision geometry loads (issue 37, item 6): PyBullet and Gazebo read it,
and a public robot stopped at the draft on it. It is read as a cylinder with a sphere at
each end; PyBullet's bounds of the loaded link say how long it came out."""

from __future__ import annotations

from pathlib import Path

import pybullet
import pytest

from robocram.robots import RobotDescription, RobotModel, draft_description
from robocram.world import World

URDF = """<robot name="stick">
  <link name="base_link"><collision><geometry><box size="0.4 0.4 0.1"/></geometry></collision>
  </link>
  <link name="pole">
    <visual><geometry><capsule radius="0.05" length="0.6"/></geometry></visual>
    <collision><origin xyz="0 0 0.4"/><geometry><capsule radius="0.05" length="0.6"/></geometry>
    </collision>
  </link>
  <joint name="turn" type="revolute"><parent link="base_link"/><child link="pole"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" velocity="1" effort="1"/></joint>
</robot>"""


def test_a_capsule_is_a_cylinder_with_round_ends(tmp_path: Path) -> None:
    path = tmp_path / "stick.urdf"
    path.write_text(URDF, encoding="utf-8")
    pole = RobotModel.from_file(path).links["pole"]
    kinds = sorted(c.geometry.kind for c in pole.collisions)
    assert kinds == ["cylinder", "sphere", "sphere"]
    ends = sorted(c.origin.position[2] for c in pole.collisions if c.geometry.kind == "sphere")
    assert ends == pytest.approx([0.1, 0.7])
    draft_description(path)  # the draft reads it too
    with World() as world:
        robot = world.add_robot(RobotDescription("stick", path, base_frame="base_link"))
        index = robot.link_index["pole"]
        low, high = pybullet.getAABB(robot.body_id, index, physicsClientId=world.physics.client())
        assert high[2] - low[2] == pytest.approx(0.7, abs=0.01)  # 0.6 + two 0.05 caps
        assert low[2] == pytest.approx(0.05 + 0.4 - 0.35, abs=0.01)

"""A handle is held from the front even when its frame points into the cabinet.

PyCRAM's apartment.urdf turns its drawers half round, so their handles' x axes point into
the cabinets; robocram's kitchen has handle frames with x out of the front.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.motion.part_path import pull_frame
from robocram.scenes import draft_environment, kitchen_urdf
from robocram.scenes.environment_model import loadable_urdf
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

APARTMENT = Path(__file__).resolve().parents[1] / "data" / "pycram" / "apartment.urdf"


def _x_in_map(world: World, part: str, handle: str, pull: Pose) -> tuple[float, float, float]:
    return quat.rotate((world.link_pose(part, handle) * pull).orientation, (1.0, 0.0, 0.0))


def test_a_handle_frame_pointing_inwards_is_turned_out_of_the_front() -> None:
    desc = draft_environment(APARTMENT).description
    world = World()
    try:
        world.add_urdf("apartment", loadable_urdf(desc.urdf, desc.stand_ins), type="environment")
        own = quat.rotate(world.link_pose("apartment", "handle_cab10_t").orientation, (1, 0, 0))
        assert own[0] == pytest.approx(1.0, abs=0.01)  # into the cabinet: the front faces -x
        for value in (0.0, 0.45):  # closed, and at its far limit (the probe steps back)
            world.set_joint_states("apartment", {"cabinet10_drawer_top_joint": value})
            pull = pull_frame(world, "apartment", "cabinet10_drawer_top_joint", "handle_cab10_t")
            out = _x_in_map(world, "apartment", "handle_cab10_t", pull)
            assert out == pytest.approx((-1.0, 0.0, 0.0), abs=0.01)
            z = quat.rotate(
                (world.link_pose("apartment", "handle_cab10_t") * pull).orientation, (0, 0, 1)
            )
            assert z[2] == pytest.approx(1.0, abs=1e-6)  # level
    finally:
        world.close()


def test_a_handle_frame_facing_out_is_kept() -> None:
    world = World()
    try:
        world.add_urdf("kitchen", kitchen_urdf(), type="environment")
        pull = pull_frame(
            world, "kitchen", "drawer_unit_drawer_3_joint", "drawer_unit_drawer_3_handle"
        )
        assert pull.position == (0.0, 0.0, 0.0)
        assert abs(quat.angle_between(pull.orientation, (0.0, 0.0, 0.0, 1.0))) < 1e-9
    finally:
        world.close()

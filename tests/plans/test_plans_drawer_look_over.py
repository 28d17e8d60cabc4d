"""A look that stops at the head's tilt limit above a thing in an opened drawer: the fetch
takes the thing where it was seen from that stand, last.

Armar6's head tilts 0.8 rad down at most. From the fetch's first stand in front of the
bowl's opened drawer (0.55 m back, the left shoulder in line with the bowl) it needs more:
the bowl lies in the lower edge of the view, not within the half that counts as seen, and
not under the view either, so neither older rule took it and the stand, the one its arms
clear the kitchen from, was never tried for the pick. Judged on PyBullet's own state: the
neck's pitch joint as the look left it, against its limit in the URDF.
"""

from __future__ import annotations

import importlib
import math
import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.execution.failures import PtuGoalNotReached
from robocram.plans.basic_actions import look_lowering
from robocram.plans.out_of_view_reach import out_of_view
from robocram.plans.tilt_limit_look import seen_at_tilt_limit
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from tests.drafts import drafted_module

fetch = importlib.import_module("robocram.plans.fetch")  # the package exports fetch()

ARMAR6 = Path(__file__).resolve().parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"
DRAWER = "drawer_unit_drawer_3"  # the bowl's
OPENING = 0.4  # [m] as the search opens it
BACK = 0.55  # [m] the fetch's first front stand (stands.REACH_DISTANCES[0])


def test_a_look_stopped_above_the_bowl_in_its_open_drawer_takes_it_where_seen(
    tmp_path: Path,
) -> None:
    module = tmp_path / "armar6.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the draft's doubts
        drafted_module(ARMAR6, module)
        scene = kitchen_scene(str(module))
    world, robot = scene.world, scene.robot
    try:
        desc = world.robot(robot).description
        for spec in desc.arms.values():
            world.set_joint_states(robot, dict(spec.parking))
        before = world.link_pose("kitchen", DRAWER)
        world.set_joint_states("kitchen", {f"{DRAWER}_joint": OPENING})
        moved = world.link_pose("kitchen", DRAWER) * before.inverse()
        world.set_pose("bowl-1", moved * world.pose("bowl-1"))
        bowl = world.pose("bowl-1").position
        shoulder = 0.09  # [m] the left shoulder's offset, the base's middle to its right
        height = world.pose(robot).position[2]
        stand = (bowl[0] + shoulder, bowl[1] - BACK, height)
        world.set_pose(robot, Pose(stand, quat.from_euler(0.0, 0.0, math.pi / 2)))
        where = PoseStamped("map", bowl, (0.0, 0.0, 0.0, 1.0))
        with simulated_robot(world, robot), pytest.raises(PtuGoalNotReached) as raised:
            look_lowering(where)
        failure = raised.value
        body = world.object(robot)
        cid = world.physics.client()
        joint = next(
            j
            for j in range(pybullet.getNumJoints(body.body_id, physicsClientId=cid))
            if pybullet.getJointInfo(body.body_id, j, physicsClientId=cid)[1] == b"neck_2_pitch"
        )
        upper = pybullet.getJointInfo(body.body_id, joint, physicsClientId=cid)[9]
        at = pybullet.getJointState(body.body_id, joint, physicsClientId=cid)[0]
        assert at == pytest.approx(upper, abs=1e-3)  # stopped at its limit, looking down
        assert failure.below_tilt
        assert not seen_at_tilt_limit(failure)  # the look does not count as had
        assert not out_of_view(failure)  # nor is the bowl under the view
        assert fetch._looked_over(failure, ("kitchen", DRAWER))
        assert not fetch._looked_over(failure, None)  # on a counter: as before
    finally:
        world.close()

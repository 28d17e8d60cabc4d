"""A pick whose way out needs a drive that fails still fails as a pick, with every try,
and takes the hand out by way of the point halfway.

The drafted Stretch stands beside the opened fridge, its arm across the shelf (household
seed 0's second stand for the milk, ``benchmarks/activity_bench.py``). Its hand reaches
the milk from the front by driving back along its heading, but the lift, 10 cm over the
grasp, is 4.3 cm over the lift's top, and no other grasp is in reach. The hand, left at the
grasp, backs out only by a drive (its arm reaches with its base), and that drive turns the
arm's tip into the fridge. That drive's ``NavigationPathBlocked`` used to leave the pick
in place of ``PickUpFailed``, and the tries' causes were lost; then the hand stayed at the
milk, and in household 0 no drive to the stand on the approach line got past the fridge.
The hand now goes halfway back first, and from there the drive's turn clears the milk.
Judged on raw PyBullet: the tool is back at the pre-grasp, 10 cm before the milk, and no
link of the robot is in the milk. The stand on the approach line that a pick tries after
these (``test_plans_pick_line_stand.py``) is left out here.
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.plans import pick_object
from robocram.plans.grasp_failures import PickUpFailed
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.tf import PoseStamped
from tests.plans.stretch_at_the_milk import MILK_Y, stretch_at_the_milk

NEAR = 0.02  # [m] the tool this near where it is meant to be (map y)
PRE_GRASP = 0.10  # [m] the front grasp's pre-grasp before its grasp


def test_a_pick_whose_drive_out_fails_keeps_its_failure_and_goes_out_by_halves(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(pick_object, "_line_stand", lambda *_: None)  # the usual tries only
    halves: list[bool] = []
    by_halves = pick_object._out_by_halves

    def spied(name: str, arm: str, pre_grasp: PoseStamped) -> bool:
        went = by_halves(name, arm, pre_grasp)
        halves.append(went)
        return went

    monkeypatch.setattr(pick_object, "_out_by_halves", spied)
    scene = stretch_at_the_milk()
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot), pytest.raises(PickUpFailed) as raised:
            pick_up_object("milk-1")
        failure = raised.value
        assert halves == [True]  # the whole way out failed, by halves it went
        assert failure.__cause__ is None  # no way out that failed is left to name
        tries = failure.causes or []
        assert len(tries) >= 4  # every grasp tried is there
        assert any(
            isinstance(c, ManipulationPoseUnreachable) and "joint limits" in str(c) for c in tries
        )  # the lift over the lift's top
        robot = world.robot(scene.robot)
        tool = robot.description.arms["arm"].tool_frame
        state = pybullet.getLinkState(
            robot.body_id, robot.link_index[tool], computeForwardKinematics=1, physicsClientId=cid
        )
        milk = world.object("milk-1")
        # the hand is out at the front grasp's pre-grasp, 10 cm before the milk's depth
        assert state[4][1] == pytest.approx(MILK_Y - PRE_GRASP, abs=NEAR)
        pybullet.performCollisionDetection(cid)
        inside = pybullet.getClosestPoints(robot.body_id, milk.body_id, 0.0, physicsClientId=cid)
        assert not inside
    finally:
        world.close()

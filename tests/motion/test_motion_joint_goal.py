"""Joint goals a motion takes: continuous joints the short way, absurd or non-finite goals
refused naming the joint and the bound (issue 42, bad 3 and the weak NaN goals)."""

from __future__ import annotations

import math

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ProcessModuleInputError
from robocram.motion import plan_arm_motion
from robocram.motion.errors import MotionInputError
from robocram.motion.joint_goal import CONTINUOUS_GOAL_BOUND
from robocram.projection import simulated_robot
from robocram.world import RobotHandle, World

ROLL = "r_forearm_roll_joint"  # continuous on the PR2


def test_a_continuous_joint_turns_the_short_way(kitchen: World) -> None:
    here = kitchen.joint_states("pr2")[ROLL]
    for goal in (here + 4 * math.pi + 0.3, here - 2 * math.pi - 0.3, 900.0):
        motion = plan_arm_motion(RobotHandle.of(kitchen, "pr2"), {ROLL: goal})
        end = motion.trajectory.points[-1].positions[0]
        assert abs(end - here) <= math.pi
        assert math.remainder(end - goal, 2 * math.pi) == pytest.approx(0.0, abs=1e-9)
        assert len(motion.trajectory.points) < 200


def test_a_continuous_goal_within_half_a_turn_is_kept_exactly(kitchen: World) -> None:
    here = kitchen.joint_states("pr2")[ROLL]
    goal = here + 3.0
    motion = plan_arm_motion(RobotHandle.of(kitchen, "pr2"), {ROLL: goal})
    assert motion.trajectory.points[-1].positions[0] == goal


@pytest.mark.parametrize("goal", [1e4, -1e300])
def test_an_absurd_continuous_goal_is_refused_naming_joint_and_bound(
    kitchen: World, goal: float
) -> None:
    with pytest.raises(MotionInputError) as caught:
        plan_arm_motion(RobotHandle.of(kitchen, "pr2"), {ROLL: goal})
    assert caught.value.joint == ROLL and caught.value.bound == CONTINUOUS_GOAL_BOUND
    assert f"{ROLL!r}" in str(caught.value) and "CONTINUOUS_GOAL_BOUND" in str(caught.value)


@pytest.mark.parametrize("goal", [math.nan, math.inf, -math.inf])
def test_a_goal_that_is_not_finite_is_refused_naming_the_joint(kitchen: World, goal: float) -> None:
    with pytest.raises(MotionInputError, match="'r_elbow_flex_joint': goal .* not a finite"):
        plan_arm_motion(RobotHandle.of(kitchen, "pr2"), {"r_elbow_flex_joint": goal})


def test_a_nan_goal_through_a_process_module_is_the_callers_mistake() -> None:
    with World() as world:
        world.add_robot("pr2")
        motion = a.motion(
            type="moving-arm-joints", arm="right", configuration={"r_elbow_flex_joint": math.nan}
        )
        with simulated_robot(world, "pr2"), pytest.raises(ProcessModuleInputError) as caught:
            perform(motion)
    assert isinstance(caught.value.error, MotionInputError)
    assert "bug in the module" not in str(caught.value)
    assert "'r_elbow_flex_joint'" in str(caught.value)

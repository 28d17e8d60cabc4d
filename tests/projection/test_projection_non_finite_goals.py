"""Goals that are not finite are the caller's mistake, never a bug in the module, and
nothing moves (issue 42, weak: NaN and inf goals)."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ProcessModuleInputError
from robocram.motion.errors import MotionInputError
from robocram.projection import simulated_robot
from robocram.tf import PoseValueError
from robocram.world import World

NAN, INF = math.nan, math.inf
CASES = {
    "going": (a.motion(type="going", target=(NAN, 0.0, 0.0)), PoseValueError),
    "turning": (a.motion(type="going", target=[[1.0, 0, 0], [NAN, 0, 0, 1]]), PoseValueError),
    "reaching": (
        a.motion(type="moving-tcp", arm="right", target=(NAN, 0.0, 1.0)),
        PoseValueError,
    ),
    "looking": (a.motion(type="looking", target=(0.0, INF, 1.0)), PoseValueError),
    "torso": (a.motion(type="moving-torso", joint_angle=INF), MotionInputError),
    "arm": (
        a.motion(type="moving-arm-joints", arm="right", configuration={"r_elbow_flex_joint": -INF}),
        MotionInputError,
    ),
}


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as made:
        made.bodies.add_floor()
        made.add_robot("pr2")
        yield made


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_goal_that_is_not_finite_is_refused_as_the_callers(world: World, case: str) -> None:
    motion, cause = CASES[case]
    before = world.joint_states("pr2"), world.pose("pr2")
    with simulated_robot(world, "pr2"), pytest.raises(ProcessModuleInputError) as caught:
        perform(motion)
    assert isinstance(caught.value.error, cause)
    assert "bug in the module" not in str(caught.value) and "finite" in str(caught.value)
    assert (world.joint_states("pr2"), world.pose("pr2")) == before

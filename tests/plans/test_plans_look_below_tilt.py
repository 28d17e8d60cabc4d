"""A head that cannot tilt down far enough lowers its torso to look.

Armar6's head tilts 46 degrees down at most: from its torso's top, a mug within reach of
its arms on a table lies below the optical axis tilted to its limit. The tabletop scene
places the mug where the camera sees it with the torso down (before: "the mug in view is
1.31 m from the shoulder, beyond its 1.08 m reach"), and the look lowers the torso until
the tilt reaches. The axis is checked on PyBullet's own link state of the camera frame.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from robocram.execution.failures import PtuGoalNotReached
from robocram.plans.basic_actions import look, look_from_above
from robocram.projection import simulated_robot
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import PoseStamped
from robocram.world import World
from tests.bullet_links import link_frame
from tests.drafts import drafted

ARMAR6 = Path(__file__).parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"


@pytest.fixture(scope="module")
def scene() -> Iterator[TabletopScene]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the draft's doubts and the missing meshes
        made = tabletop_scene(drafted(ARMAR6).description)
    yield made
    made.world.close()


def _off_axis(world: World, robot: str, target: tuple[float, float, float]) -> float:
    """[rad] between the camera's optical axis (z) and the target, from PyBullet's link
    state of the camera frame."""
    position, rotation = link_frame(
        world.object(robot).body_id,
        world.physics.client(),
        world.robot(robot).description.cameras[0].frame,
    )
    towards = np.asarray(target) - position
    cosine = rotation[:, 2] @ towards / np.linalg.norm(towards)
    return math.acos(min(1.0, cosine))


def test_a_head_tilted_to_its_limit_above_the_mug_lowers_the_torso(scene: TabletopScene) -> None:
    world, robot = scene.world, scene.robot
    torso = world.robot(robot).description.torso_joint
    assert torso is not None
    limits = world.bodies.joint_limits(robot, torso)
    mug = world.pose("mug-1").position
    target = PoseStamped("map", mug)
    with simulated_robot(world, robot):
        world.set_joint_states(robot, {torso: limits.upper})
        with pytest.raises(PtuGoalNotReached) as failed:
            look(target)  # from the top, the tilt stops above the mug
        assert failed.value.below_tilt
        assert _off_axis(world, robot, mug) > math.radians(3)
        look_from_above(target)
    assert world.joint_states(robot)[torso] < limits.upper - 0.05
    assert _off_axis(world, robot, mug) < math.radians(1)

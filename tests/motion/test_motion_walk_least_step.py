"""A walk near a contact is never coarser than the dense check (issue 37).

The drafted Stretch closes its gripper on the kitchen's bowl (the zoo's bowl transport, as
the grip left it): the right fingertip grazes the bowl's wall 0.4 mm deep over s = 0.03
to 0.045 of the closing and clears it again. The fingertip starts 0.4 mm from the bowl, so
the walk takes its least step there; speed10's tighter travel bound (the fingers' own
travel, not the sum over both joints) stretched that step past the graze and the closing
was found free, which sent the Stretch on with a grip whose finger cuts the bowl. The
least step stays the dense check's spacing on the rigid bound: the graze is found, as
:func:`first_collision` finds it. The graze itself is judged by raw PyBullet.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.hand_contact import HandContact
from robocram.motion.segment_check import CheckCounter, first_collision, segment_free, start_travel
from robocram.motion.travel_bound import TravelBound
from robocram.robots import MissingMeshWarning
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import RobotHandle, World

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
FINGERS = ("joint_gripper_finger_right", "joint_gripper_finger_left")
OPEN, CLOSED = 0.6, 0.016875  # [rad] the grip's closing
ARM = {
    "joint_lift": 0.7640465681715695,
    **{f"joint_arm_l{k}": 0.11002470176692514 for k in range(4)},
    "joint_wrist_yaw": 1.2947682114604542,
    "joint_wrist_pitch": -1.57,
    "joint_wrist_roll": -0.29333122329016764,
    "joint_head_pan": -1.7347190502212346,
    "joint_head_tilt": -0.8380196356412546,
}  # as the zoo's bowl transport stood at the grip
STAND = Pose(
    (-1.454286014631948, 1.1042909053077918, 0.0),
    (0.0, 0.0, 0.9999625754670496, 0.008651454519632375),
)
BOWL = Pose((-1.3999999761581423, 1.760000000000001, 0.5981630207999858), (0.0, 0.0, 0.0, 1.0))
TIP = "link_gripper_fingertip_right"


def _tip_depth(world: World, robot: str, q: np.ndarray) -> float:
    """[m] the right fingertip's signed distance to the bowl at fingers ``q``, raw PyBullet."""
    world.set_joint_states(robot, dict(zip(FINGERS, q.tolist(), strict=True)))
    body = world.object(robot)
    cid = world.physics.client()
    points = pybullet.getClosestPoints(
        body.body_id, world.object("bowl-1").body_id, 0.05,
        linkIndexA=body.link_index[TIP], physicsClientId=cid,
    )  # fmt: skip
    return min((p[8] for p in points), default=0.05)


def test_closing_fingers_graze_found_like_the_dense_check() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)  # the camera's meshes are left out
        scene = kitchen_scene(STRETCH)
    world = scene.world
    world.set_joint_states("kitchen", {"drawer_unit_drawer_3_joint": 0.4})
    world.set_pose(scene.robot, STAND)
    world.set_pose("bowl-1", BOWL)
    world.set_joint_states(scene.robot, {**ARM, **dict.fromkeys(FINGERS, OPEN)})
    robot = RobotHandle.of(world, scene.robot)
    qa, qb = np.array([OPEN, OPEN]), np.array([CLOSED, CLOSED])
    # raw PyBullet: the fingertip cuts the bowl a little way into the closing, then clears
    depths = [_tip_depth(world, scene.robot, qa + (qb - qa) * s) for s in (0.0, 0.035, 0.06)]
    assert depths[0] > 0.0 and depths[1] < -1e-4 and depths[2] > 0.0, depths
    world.set_joint_states(scene.robot, dict.fromkeys(FINGERS, OPEN))
    hand = HandContact.of(["link_gripper_finger_right"], "bowl-1")  # the grip's one-sided hold
    checker = BulletScene(
        robot, FINGERS, allowed_pairs=[("link_gripper_finger_right", "bowl-1")], hand=hand
    )
    bound = TravelBound.of(robot, FINGERS)
    with checker.posed():
        checker.clearances(qa)
        tight = start_travel(checker, qa, qb, bound)
    # the cause: the tight travel's 1 cm step would jump the graze (ends by s = 0.046)
    assert bound.max_link_travel / tight > 0.05 > bound.max_link_travel / bound.travel(qa, qb)
    found = first_collision(checker, qa, qb, bound, CheckCounter())
    assert found is not None and (TIP, "bowl-1") in found[1]
    assert not segment_free(checker, qa, qb, bound, CheckCounter())
    world.close()

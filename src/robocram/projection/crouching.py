"""A legged robot crouches in projection: its body down (or up) along a checked, timed way.

The robot's legs (chains off its body named like legs, :func:`~robocram.robots.draft.stance.legs`)
bend while its root goes straight down, its soles where they stand
(:mod:`~robocram.motion.crouch_path`). How deep it crouches is read off the robot as it
stands: how far its feet have come up towards the root from where its standing legs (the
description's ``stance``, else each joint's resting value) hold them, so nothing is kept
beside the world. The way is checked before anything moves, densely (every
:data:`~robocram.motion.crouch_path.DEPTH_STEP` of depth), against the world with what the
robot holds (its contacts at the start allowed, as for the arms) and against itself; then
it is followed, so traces, replay and viewers see the body go down and up.
"""

from __future__ import annotations

import numpy as np

from robocram.execution.failures import TorsoGoalUnreachable, TorsoPathBlocked
from robocram.kinematics.crouch import CrouchUnreachable
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.motion import joint_limits
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.crouch_path import CrouchCurve, crouch_curve, time_crouch
from robocram.motion.self_path_check import SelfPathCheck
from robocram.projection.errors import ProjectionError
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.robots import LoadedDescription, RobotModel
from robocram.robots.model_pose import resting_value
from robocram.tf import Pose

SAME_DEPTH = 1e-4  # [m] a crouch asked this near where the body is moves nothing


def crouch_feet(description: LoadedDescription) -> list[str]:
    """The feet (links) of the robot's legs: empty for a robot that cannot crouch."""
    hands = tuple(arm.end_effector_link for arm in description.arms.values())
    return list(description.model.derived(_Feet).of(hands))


class _Feet:
    """A model's feet per set of hands (end-effector links), found once: every projection
    environment asks."""

    def __init__(self, model: RobotModel) -> None:
        self.model = model
        self.found: dict[tuple[str, ...], tuple[str, ...]] = {}

    def of(self, hands: tuple[str, ...]) -> tuple[str, ...]:
        from robocram.robots.draft.stance import legs  # noqa: PLC0415 - the draft package
        # loads pinocchio and coal, which importing projection must not (test_import_cost)

        if hands not in self.found:
            self.found[hands] = tuple(leg.foot for leg in legs(self.model, hands))
        return self.found[hands]


def can_crouch(description: LoadedDescription) -> bool:
    """Whether the robot stands on legs it can bend (two or more)."""
    return len(crouch_feet(description)) >= 2


def crouch_depth(robot: ProjectedRobot) -> float:
    """How deep [m] ``robot`` crouches now: 0 standing on its standing legs."""
    desc = robot.description
    feet = crouch_feet(desc)
    if not feet:
        return 0.0
    kin = robot_kinematics(desc.model)
    now = robot.world.joint_states(robot.name)
    standing = now | _standing_legs(robot)
    raised = [
        kin.frame_pose(foot, now).position[2] - kin.frame_pose(foot, standing).position[2]
        for foot in feet
    ]
    return float(np.mean(raised))


def crouch(robot: ProjectedRobot, depth: float) -> float:
    """Bend ``robot``'s legs until its body stands ``depth`` [m] lower than standing (0:
    stand up), along a checked, timed trajectory; return the depth reached.

    Raises:
        ProjectionError: the robot has no legs to crouch with, or ``depth`` is negative.
        TorsoGoalUnreachable: the legs cannot keep the soles at some depth on the way.
        TorsoPathBlocked: the way collides (the robot with the world or itself); nothing
            moved.
    """
    desc = robot.description
    feet = crouch_feet(desc)
    if len(feet) < 2:
        raise ProjectionError(
            f"{robot.name} has no legs to crouch with (found feet {feet}); send crouching "
            "motions to legged robots only"
        )
    if not (np.isfinite(depth) and depth >= 0.0):
        raise ProjectionError(f"a crouch's depth must be 0 or more [m], got {depth}")
    start = crouch_depth(robot)
    if abs(depth - start) < SAME_DEPTH:
        return start
    standing = robot.world.joint_states(robot.name) | _standing_legs(robot)
    try:
        curve = crouch_curve(desc.model, feet, standing, start, depth)
    except CrouchUnreachable as err:
        raise TorsoGoalUnreachable(
            f"{robot.name} cannot crouch {depth:.3f} m: {err}", goal=depth, limits=(0.0, depth)
        ) from err
    standing_z = robot.base_pose().position[2] + start
    checked = planned_against(robot)
    _check(robot, curve, standing_z)
    limits = joint_limits(desc, ("z", *curve.joints))
    follow(robot, time_crouch(robot.name, curve, standing_z, limits), checked)
    return crouch_depth(robot)


def _standing_legs(robot: ProjectedRobot) -> dict[str, float]:
    """The leg joints' standing values: the description's stance, else resting values."""
    desc = robot.description
    model = desc.model
    names = {
        joint.name
        for foot in crouch_feet(desc)
        for joint in model.chain(model.root_link, foot)
        if joint.movable
    }
    return {name: desc.stance.get(name, resting_value(model.joints[name])) for name in names}


def _check(robot: ProjectedRobot, curve: CrouchCurve, standing_z: float) -> None:
    """Raise ``TorsoPathBlocked`` where the way along ``curve`` collides."""
    world, handle = robot.world, robot.handle
    scene = BulletScene(handle, ())
    with scene.posed():
        start = scene.colliding_now()
    judge = BulletScene(handle, (), allowed_pairs=start)
    pose = world.pose(robot.name)
    hit: tuple[float, list[tuple[str, str]]] | None = None
    try:
        with judge.posed():
            for k, depth in enumerate(curve.depths.tolist()):
                x, y, _ = pose.position
                world.set_pose(robot.name, Pose((x, y, standing_z - depth), pose.orientation))
                world.set_joint_states(
                    robot.name, dict(zip(curve.joints, curve.legs[k], strict=True))
                )
                pairs = judge.colliding_now(first_only=True)
                if pairs:
                    hit = (k / max(len(curve.depths) - 1, 1), pairs)
                    break
    finally:
        world.set_pose(robot.name, pose)
    if hit is None:
        hit = SelfPathCheck.of(handle, curve.joints).first_collision(curve.legs.tolist())
    if hit is not None:
        fraction, pairs = hit
        raise TorsoPathBlocked(
            f"{robot.name}'s crouch from {curve.depths[0]:.3f} to {curve.depths[-1]:.3f} m "
            f"collides {fraction:.0%} of the way: {pairs}; it did not move",
            goal=float(curve.depths[-1]),
            colliding_pairs=tuple(pairs),
            path_fraction=fraction,
        )

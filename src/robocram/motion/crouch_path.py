"""A crouch as a timed trajectory: the base's height and the legs' joints together.

A legged robot crouches by bending its legs while its root goes straight down, its soles
where they stand (:func:`~robocram.kinematics.crouch.crouched`). The way down (or up) is
one curve in joint space, a function of the depth: the legs are solved at depths
:data:`DEPTH_STEP` apart (nearer where a joint turns fast: a knee bends out of straight
as the square root of the depth) and read between them linearly. The way along the curve is timed
as one coordinate (:func:`~robocram.motion.time_parameterize`, as every motion), measured
so that every step takes its slowest joint as long at full speed, under the tightest
limits the joints allow along it: a joint turning ``q'`` per unit of the way turns
``q' * v`` at speed ``v``, and the curve's bend adds ``q'' * v**2`` to its acceleration,
so the way's limits leave :data:`SHARE` of each joint's for that.
The trajectory's joints are ``z`` (the base's height in map, as a flight's) and the leg
joints: recording, replay and the audit see the body go down and up.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from robocram.kinematics.crouch import crouched
from robocram.motion.errors import MotionError
from robocram.motion.joint_limits import JointLimits
from robocram.motion.joint_trajectory import FloatArray, JointTrajectory, PointTable
from robocram.motion.time_parameterization import time_parameterize
from robocram.robots import RobotModel
from robocram.tf import Pose
from robocram.world import RobotHandle

DEPTH_STEP = 0.005  # [m] between two solved crouches along the way, at most
TURN = 0.01  # [rad | m] a step turning a joint more is halved (a knee leaving straight)
SHARE = 0.5  # of each joint's velocity and acceleration limits the depth's timing uses
CROUCH_KIND = "crouch"  # the trajectories' kind


@dataclass(frozen=True)
class CrouchCurve:
    """The legs' joints along the way from one depth to another, ``DEPTH_STEP`` apart
    or nearer (each step turning no joint more than ``TURN``).

    ``depths`` [m] (from the first to the last, either way), ``legs`` (depths, joints)
    [rad | m] in the order of ``joints``.
    """

    joints: tuple[str, ...]
    depths: FloatArray
    legs: FloatArray


def crouch_curve(
    model: RobotModel,
    feet: Sequence[str],
    standing: Mapping[str, float],
    start: float,
    goal: float,
) -> CrouchCurve:
    """The legs from depth ``start`` to ``goal`` [m] (0: standing at ``standing``).

    Raises:
        CrouchUnreachable: a leg cannot keep its foot at some depth on the way.
    """
    count = max(2, math.ceil(abs(goal - start) / DEPTH_STEP) + 1)
    solved = {
        d: crouched(model, feet, standing, d) for d in np.linspace(start, goal, count).tolist()
    }
    joints = tuple(solved[start])
    depths = list(solved)
    k = 0
    while k < len(depths) - 1:  # halve each step that turns a joint more than TURN
        a, b = solved[depths[k]], solved[depths[k + 1]]
        middle = 0.5 * (depths[k] + depths[k + 1])
        if max(abs(a[j] - b[j]) for j in joints) > TURN and abs(depths[k + 1] - middle) > 1e-6:
            solved[middle] = crouched(model, feet, standing, middle)
            depths.insert(k + 1, middle)
            continue
        k += 1
    rows = [[solved[d][name] for name in joints] for d in depths]
    return CrouchCurve(joints, np.array(depths), np.array(rows))


def time_crouch(
    robot: str, curve: CrouchCurve, standing_z: float, limits: Sequence[JointLimits]
) -> JointTrajectory:
    """The trajectory of ``("z", *curve.joints)`` along ``curve``, the base's height
    ``standing_z`` [m] (map) minus the depth; ``limits`` those of ``"z"`` and the joints.

    Raises:
        MotionError: ``limits`` are not for ``("z", *curve.joints)``.
    """
    names = ("z", *curve.joints)
    if tuple(lim.name for lim in limits) != names:
        raise MotionError(
            f"crouch limits are for {[lim.name for lim in limits]}, its joints are "
            f"{list(names)}; pass joint_limits(desc, ('z', *legs))"
        )
    table = np.column_stack([standing_z - curve.depths, curve.legs])
    along = _along(table, limits)
    slope, bend = _derivatives(along, table)
    timed = time_parameterize(
        robot, ("along",), [[0.0], [along[-1]]], [_along_limits(slope, bend, limits, along)],
        kind=CROUCH_KIND,
    )  # fmt: skip
    points = timed.points
    assert isinstance(points, PointTable)  # time_parameterize makes tables
    s = points.positions[:, 0]
    speed = np.array([p.velocities[0] for p in points])[:, None]
    accel = np.array([p.accelerations[0] for p in points])[:, None]
    dq = _interp_columns(s, along, slope)
    positions = _interp_columns(s, along, table)
    velocities = dq * speed
    accelerations = dq * accel + _interp_columns(s, along, bend) * speed**2
    return JointTrajectory(
        robot, names, PointTable(positions, velocities, accelerations, points.times), CROUCH_KIND
    )


def _along(table: FloatArray, limits: Sequence[JointLimits]) -> FloatArray:
    """Per row of ``table``: how far along the way it is, each step as long as its slowest
    joint takes at its velocity limit [s]: a joint that moves fast near one end (a knee
    bending out of straight) no longer slows the whole way."""
    velocity = np.array([lim.velocity for lim in limits])
    steps = np.max(np.abs(np.diff(table, axis=0)) / velocity, axis=1)
    return np.concatenate(([0.0], np.cumsum(np.maximum(steps, 1e-9))))


def _interp_columns(at: FloatArray, along: FloatArray, values: FloatArray) -> FloatArray:
    """Each column of ``values`` (one row per place of ``along``) read at ``at``."""
    return np.column_stack([np.interp(at, along, values[:, k]) for k in range(values.shape[1])])


def _derivatives(along: FloatArray, table: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Per row: each joint's first and second derivative along the way."""
    if len(along) < 3:
        slope = np.repeat(np.diff(table, axis=0) / np.diff(along)[:, None], len(along), axis=0)
        return slope, np.zeros_like(table)
    slope = np.gradient(table, along, axis=0)
    return slope, np.gradient(slope, along, axis=0)


def _along_limits(
    slope: FloatArray, bend: FloatArray, limits: Sequence[JointLimits], along: FloatArray
) -> JointLimits:
    """The way's limits: within :data:`SHARE` of every joint's (the base's height
    included), the rest of each acceleration left to the way's bend."""
    velocity = acceleration = jerk = math.inf
    for k, lim in enumerate(limits):
        most = float(np.max(np.abs(slope[:, k])))
        curve = float(np.max(np.abs(bend[:, k])))
        if most > 0.0:
            velocity = min(velocity, SHARE * lim.velocity / most)
            acceleration = min(acceleration, SHARE * lim.acceleration / most)
            jerk = min(jerk, SHARE * lim.jerk / most)
        if curve > 0.0:  # the bend's share: q'' v^2 within the rest of the limit
            velocity = min(velocity, math.sqrt((1.0 - SHARE) * lim.acceleration / curve))
    return JointLimits("along", 0.0, float(along[-1]), velocity, acceleration, jerk)


def is_height_and_joints(names: Sequence[str]) -> bool:
    """Whether a trajectory of ``names`` moves the base's height ``z`` and joints (a
    crouch), not a flight's whole body."""
    return len(names) > 1 and names[0] == "z" and "x" not in names


def put_height_and_joints(robot: RobotHandle, values: Mapping[str, float]) -> None:
    """Put ``robot``'s base at height ``values["z"]`` [m] (map; x, y and turn kept) and
    its joints at the other values; what it holds follows."""
    world = robot.world
    pose = world.pose(robot.name)
    x, y, _ = pose.position
    world.set_pose(robot.name, Pose((x, y, values["z"]), pose.orientation))
    world.set_joint_states(robot.name, {k: v for k, v in values.items() if k != "z"})

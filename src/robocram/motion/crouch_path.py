"""A crouch as a timed trajectory: the base's height and the legs' joints together.

A legged robot crouches by bending its legs while its root goes straight down, its soles
where they stand (:func:`~robocram.kinematics.crouch.crouched`). The way down (or up) is
one curve in joint space, a function of the depth: the legs are solved at depths
:data:`DEPTH_STEP` apart and read between them linearly. The depth is timed as one
coordinate (:func:`~robocram.motion.time_parameterize`, as every motion), under the
tightest limits the legs allow along the curve: a joint turning ``q'`` [rad/m] per metre
of depth turns ``q' * v`` at depth speed ``v``, and the curve's bend adds ``q'' * v**2``
to its acceleration, so the depth's limits leave :data:`SHARE` of each joint's for that.
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

DEPTH_STEP = 0.005  # [m] between two solved crouches along the way
SHARE = 0.5  # of each joint's velocity and acceleration limits the depth's timing uses
CROUCH_KIND = "crouch"  # the trajectories' kind


@dataclass(frozen=True)
class CrouchCurve:
    """The legs' joints along the way from one depth to another, ``DEPTH_STEP`` apart.

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
    depths = np.linspace(start, goal, count)
    rows: list[list[float]] = []
    joints: tuple[str, ...] = ()
    for depth in depths.tolist():
        values = crouched(model, feet, standing, depth)
        joints = joints or tuple(values)
        rows.append([values[name] for name in joints])
    return CrouchCurve(joints, depths, np.array(rows))


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
    depths, legs = curve.depths, curve.legs
    slope, bend = _derivatives(depths, legs)
    depth_limits = _depth_limits(slope, bend, limits, depths)
    timed = time_parameterize(
        robot, ("depth",), [[depths[0]], [depths[-1]]], [depth_limits], kind=CROUCH_KIND
    )
    d = timed.positions()[:, 0]
    table = timed.points
    assert isinstance(table, PointTable)  # time_parameterize makes tables
    speed = np.array([p.velocities[0] for p in table])
    accel = np.array([p.accelerations[0] for p in table])
    q = _interp_columns(d, depths, legs)
    dq = _interp_columns(d, depths, slope)
    ddq = _interp_columns(d, depths, bend)
    positions = np.column_stack([standing_z - d, q])
    velocities = np.column_stack([-speed, dq * speed[:, None]])
    accelerations = np.column_stack([-accel, dq * accel[:, None] + ddq * (speed**2)[:, None]])
    points = PointTable(positions, velocities, accelerations, table.times)
    return JointTrajectory(robot, names, points, CROUCH_KIND)


def _interp_columns(d: FloatArray, depths: FloatArray, values: FloatArray) -> FloatArray:
    """Each column of ``values`` (one row per depth of ``depths``) read at ``d``."""
    order = np.argsort(depths)
    xs = depths[order]
    return np.column_stack([np.interp(d, xs, values[order, k]) for k in range(values.shape[1])])


def _derivatives(depths: FloatArray, legs: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Per depth: each joint's first and second derivative along the depth [per m, m^2]."""
    if len(depths) < 3:
        slope = np.repeat(np.diff(legs, axis=0) / np.diff(depths)[:, None], len(depths), axis=0)
        return slope, np.zeros_like(legs)
    slope = np.gradient(legs, depths, axis=0)
    bend = np.gradient(slope, depths, axis=0)
    return slope, bend


def _depth_limits(
    slope: FloatArray, bend: FloatArray, limits: Sequence[JointLimits], depths: FloatArray
) -> JointLimits:
    """The depth's limits: within :data:`SHARE` of every joint's along the curve, the
    base's height (``limits[0]``, moving one to one) included."""
    height, legs = limits[0], limits[1:]
    velocity, acceleration = SHARE * height.velocity, SHARE * height.acceleration
    jerk = SHARE * height.jerk
    for k, lim in enumerate(legs):
        most = float(np.max(np.abs(slope[:, k])))
        curve = float(np.max(np.abs(bend[:, k])))
        if most > 0.0:
            velocity = min(velocity, SHARE * lim.velocity / most)
            acceleration = min(acceleration, SHARE * lim.acceleration / most)
            jerk = min(jerk, SHARE * lim.jerk / most)
        if curve > 0.0:  # the bend's share: q'' v^2 within the rest of the limit
            velocity = min(velocity, math.sqrt((1.0 - SHARE) * lim.acceleration / curve))
    low, high = float(np.min(depths)), float(np.max(depths))
    return JointLimits("depth", low, high, velocity, acceleration, jerk)


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

"""A legged robot's crouch: its root lowered straight down, its feet where they stand.

Bent knees lower the shoulders: TALOS holds the bowl drawer's handle, 0.64 m under its
shoulders, from the front only with its body 0.15 m lower (issue 37,
``benchmarks/handle_hold_probe.py --lower``). Each leg's joints (the chain from the root
link to its foot) are solved by damped least squares on the robot's pinocchio model so
that the foot keeps its pose while the root goes ``depth`` down along its own z (upright:
the world's). A straight knee cannot shorten the leg at first order, so the search starts
from every leg joint turned a little towards the middle of its range (a knee that cannot
overstretch then bends the way it can).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from robocram.kinematics.errors import KinematicsError
from robocram.kinematics.robot_kinematics import RobotKinematics, pose_to_se3, robot_kinematics
from robocram.robots import RobotModel
from robocram.robots.lazy_library import LazyLibrary
from robocram.tf import Pose

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

NUDGE = 0.1  # [rad] each leg joint's start, towards the middle of its range
DAMPING = 1e-3  # the least squares' damping (squared: 1e-6)
TOLERANCE = 1e-6  # [m | rad] the foot's pose error at which a leg counts as solved
STEPS = 200  # iterations per leg at most


class CrouchUnreachable(KinematicsError):
    """No leg joints within limits keep a foot in place at the asked depth.

    Attributes:
        foot: the foot's link.
        depth: the depth asked [m].
        error: the least pose error reached [m | rad].
    """

    def __init__(self, robot: str, foot: str, depth: float, error: float) -> None:
        self.foot, self.depth, self.error = foot, depth, error
        super().__init__(
            f"{robot} cannot crouch {depth:.3f} m: its foot {foot!r} stays {error * 1000:.1f} "
            "mm (or mrad) off within its leg's limits; ask a smaller depth"
        )


def crouched(
    model: RobotModel,
    feet: Sequence[str],
    standing: Mapping[str, float],
    depth: float,
    seed: Mapping[str, float] | None = None,
) -> dict[str, float]:
    """The leg joints' values [rad | m] that keep each of ``feet`` (links) where it stands
    (the joints at ``standing``; others at their defaults) with the root ``depth`` [m] lower.
    ``seed``: leg joints each leg's search starts from, unnudged (a neighbouring depth's
    solution), instead of ``standing`` nudged.

    Raises:
        CrouchUnreachable: a leg cannot keep its foot in place within its limits.
        KinematicsError: a foot is not a link of ``model`` (UnknownNameError).
    """
    kin = robot_kinematics(model)
    q = kin.configuration(standing)
    start = q if seed is None else kin.configuration(dict(standing) | dict(seed))
    values: dict[str, float] = {}
    for foot in feet:
        goal = Pose((0.0, 0.0, depth)) * kin.frame_pose(foot, standing)
        values.update(_leg(kin, model, foot, pose_to_se3(goal), start, depth, seed is None))
    return values


def _leg(
    kin: RobotKinematics,
    model: RobotModel,
    foot: str,
    goal: pin.SE3,
    q: np.ndarray,
    depth: float,
    nudge: bool = True,
) -> dict[str, float]:
    """One leg's joints putting ``foot`` at ``goal`` (in the root link), from ``q``
    (``nudge``: each joint first turned towards the middle of its range)."""
    joints = [kin.joint(j.name) for j in model.chain(model.root_link, foot) if j.movable]
    turning = [info.name for info in joints if info.continuous]
    if turning:
        raise KinematicsError(
            f"{model.name}'s leg to {foot!r} has continuous joints {turning}: a crouch needs "
            "a leg of revolute and prismatic joints; give them limits in the URDF"
        )
    q = q.copy()
    for info in joints:
        if nudge and depth > 0.0 and math.isfinite(info.lower) and math.isfinite(info.upper):
            middle = 0.5 * (info.lower + info.upper)
            now = q[info.idx_q]
            q[info.idx_q] = now + math.copysign(min(NUDGE, abs(middle - now)), middle - now)
    fid = kin.frame_id(foot)
    columns = [info.idx_v for info in joints]
    error = math.inf
    for _ in range(STEPS):
        pin.forwardKinematics(kin.model, kin.data, q)
        at = pin.updateFramePlacement(kin.model, kin.data, fid)
        twist = pin.log6(at.actInv(goal)).vector
        error = float(np.linalg.norm(twist))
        if error < TOLERANCE:
            break
        jac = pin.computeFrameJacobian(kin.model, kin.data, q, fid, pin.ReferenceFrame.LOCAL)
        j = jac[:, columns]
        step = j.T @ np.linalg.solve(j @ j.T + DAMPING**2 * np.eye(6), twist)
        for info, d in zip(joints, step, strict=True):
            q[info.idx_q] = min(max(q[info.idx_q] + d, info.lower), info.upper)
    if error >= TOLERANCE:
        raise CrouchUnreachable(model.name, foot, depth, error)
    return {info.name: float(q[info.idx_q]) for info in joints}

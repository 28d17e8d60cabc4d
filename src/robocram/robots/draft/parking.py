"""A parking pose for a drafted arm: within the joint limits, hand low beside the shoulder.

Parked arms must stay out of the camera's view and off the table in front: the pose puts
the wrist :data:`BELOW` under and :data:`OUTWARD` beside its shoulder, links above the
floor and outside the body's middle. It is a seeded sampled search over the joint limits
(no collision check: ``robocram robot check`` drives the arm there and reports).
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Sequence

import numpy as np

from robocram.robots.draft.link_poses import joint_motion, link_poses
from robocram.robots.robot_model import RobotModel
from robocram.tf import Pose

BELOW = 0.35  # [m] from the shoulder down to the parked wrist
OUTWARD = 0.15  # [m] from the shoulder outwards (away from the body's middle)
SAMPLES = 1500
REFINE_ROUNDS = 4
LOOK_DOWN = math.radians(30.0)  # [rad] a parked neck holds the camera looking this far down
FLOOR_CLEARANCE = 0.15  # [m] every arm joint stays this high over the root link (the floor)


def joint_range(model: RobotModel, joint: str) -> tuple[float, float]:
    """``joint``'s limits [rad | m], a full turn each way where the URDF gives none."""
    spec = model.joints[joint]
    lower = -math.pi if spec.lower is None or not math.isfinite(spec.lower) else spec.lower
    upper = math.pi if spec.upper is None or not math.isfinite(spec.upper) else spec.upper
    return lower, upper


class ChainPoses:
    """Forward kinematics of one arm chain only, for a fast search: ``chain`` holds every
    joint from the first arm joint's parent down to ``wrist``."""

    def __init__(self, model: RobotModel, joints: Sequence[str], wrist: str) -> None:
        self.model = model
        self.joints = tuple(joints)
        self.base = link_poses(model)[model.joints[joints[0]].parent]
        self.chain = model.chain(model.joints[joints[0]].parent, wrist)

    def poses(self, values: Sequence[float]) -> list[Pose]:
        """The pose of each link along the chain in the root link, for ``values``."""
        by_name = dict(zip(self.joints, values, strict=True))
        pose, found = self.base, []
        for joint in self.chain:
            pose = pose * joint.origin
            value = by_name.get(joint.name, 0.0)
            if joint.mimic is not None and joint.mimic.joint in by_name:  # a coupled follower
                value = joint.mimic.multiplier * by_name[joint.mimic.joint] + joint.mimic.offset
            if joint.movable and value:
                pose = pose * joint_motion(joint.axis, joint.type, value)
            found.append(pose)
        return found

    def points(self, values: Sequence[float]) -> list[np.ndarray]:
        """The position of each link along the chain [m]."""
        return [np.asarray(pose.position) for pose in self.poses(values)]


def _cost(chain: ChainPoses, values: Sequence[float], goal: np.ndarray, side: float) -> float:
    points = chain.points(values)
    cost = float(np.linalg.norm(points[-1] - goal))
    for point in points:
        cost += 2.0 * max(0.0, FLOOR_CLEARANCE - float(point[2]))
        if side:
            cost += max(0.0, float(abs(chain.base.position[1]) - side * point[1]))
    return cost


def parking_pose(
    model: RobotModel, joints: Sequence[str], wrist: str, seed: int = 0
) -> dict[str, float]:
    """Joint values [rad | m] within limits that park the arm; ``seed`` fixes the search."""
    chain = ChainPoses(model, joints, wrist)
    shoulder = chain.points([0.0] * len(joints))[0]
    side = float(np.sign(shoulder[1])) if abs(shoulder[1]) > 0.05 else 0.0
    goal = shoulder + np.array((0.0, side * OUTWARD, -BELOW))
    goal[2] = max(goal[2], 2 * FLOOR_CLEARANCE)  # an arm mounted low parks above the floor
    return _search(model, joints, lambda values: _cost(chain, values, goal, side), seed)


def neck_pose(
    model: RobotModel,
    joints: Sequence[str],
    camera: str,
    offset: Pose | None = None,
    seed: int = 0,
) -> dict[str, float]:
    """Neck joint values [rad] within limits that hold the optical frame looking ahead.

    Ahead is :data:`LOOK_DOWN` below the root link's x, with the image's x to the right;
    ``offset`` is the optical frame's pose in ``camera`` (one added in code).
    """
    chain = ChainPoses(model, joints, camera)
    wanted = np.array((math.cos(LOOK_DOWN), 0.0, -math.sin(LOOK_DOWN)))

    def cost(values: Sequence[float]) -> float:
        axes = (chain.poses(values)[-1] * (offset or Pose())).matrix()[:3, :3]
        return float(2.0 - axes[:, 2] @ wanted - 0.5 * (axes[:, 0] @ (0.0, -1.0, 0.0)))

    return _search(model, joints, cost, seed)


def _search(
    model: RobotModel,
    joints: Sequence[str],
    cost: Callable[[Sequence[float]], float],
    seed: int,
) -> dict[str, float]:
    """Seeded sampling within the limits, then coordinate descent on ``cost``."""
    limits = [joint_range(model, j) for j in joints]
    rng = random.Random(seed)
    best = [min(max(0.0, lo), hi) for lo, hi in limits]
    best_cost = cost(best)
    for _ in range(SAMPLES):
        values = [rng.uniform(lo, hi) for lo, hi in limits]
        value = cost(values)
        if value < best_cost:
            best, best_cost = values, value
    step = 0.2
    for _ in range(REFINE_ROUNDS):
        for i, (lo, hi) in enumerate(limits):
            for delta in (-step, step):
                trial = list(best)
                trial[i] = min(max(trial[i] + delta, lo), hi)
                value = cost(trial)
                if value < best_cost:
                    best, best_cost = trial, value
        step /= 2
    return {j: rounded_inside(v, lim) for j, v, lim in zip(joints, best, limits, strict=True)}


def rounded_inside(value: float, limits: tuple[float, float]) -> float:
    """``value`` to 3 decimals, rounded towards the inside of ``limits``."""
    rounded = round(value, 3)
    if rounded > limits[1]:
        return math.floor(limits[1] * 1000) / 1000
    if rounded < limits[0]:
        return math.ceil(limits[0] * 1000) / 1000
    return rounded

"""Configurations along a stored trajectory, dense enough that nothing is stepped over.

Between two stored points the robot moves on the straight joint segment (linear
interpolation, as the replay does). The segment is cut into ``n`` equal steps, the least
``n`` with every joint moving at most ``joint_step`` and every point of the robot and of
what it holds at most ``point_step`` per step. A point's travel is bounded by the joints'
levers, whatever the other joints do:

- a revolute joint moves a link by at most (the rigid lengths between the joint and the
  link, prismatic travel included, plus the link's radius) times its angle;
- a prismatic joint, and the base's ``x`` and ``y``, by the distance itself;
- the base's ``yaw`` as a revolute joint at the robot's root.

A mimic joint's lever is added to its master's, times its multiplier. Radii are read from
PyBullet's link bounds about the link's frame; a held object counts as part of the link it
is attached to.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from robocram.robots import RobotModel
from robocram.world import RawDistances, RobotHandle

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Levers:
    """Per joint (and base joint): the most a point moves per unit of it [m/rad | m/m]."""

    per_joint: Mapping[str, float]

    @classmethod
    def of(cls, robot: RobotHandle, model: RobotModel, held: Mapping[str, str]) -> Levers:
        """The levers of ``robot`` as it stands, holding ``held`` (object -> link)."""
        radius = _radii(robot, held)
        reach = _reach_below(model, radius)
        levers: dict[str, float] = {}
        for joint in model.movable_joints():
            levers[joint.name] = 1.0 if joint.type == "prismatic" else reach[joint.child]
        for joint in model.movable_joints():
            if joint.mimic is not None and joint.mimic.joint in levers:
                levers[joint.mimic.joint] += abs(joint.mimic.multiplier) * levers[joint.name]
        turn = reach[model.root_link]
        levers |= {"x": 1.0, "y": 1.0, "z": 1.0, "roll": turn, "pitch": turn, "yaw": turn}
        return cls(levers)

    def steps(
        self, names: Sequence[str], delta: FloatArray, joint_step: float, point_step: float
    ) -> int:
        """Steps for a move of ``delta`` (per joint of ``names``) within both bounds."""
        moved = np.abs(delta)
        travel = sum(
            self.per_joint.get(n, 0.0) * float(d) for n, d in zip(names, moved, strict=True)
        )
        return max(1, math.ceil(float(np.max(moved)) / joint_step), math.ceil(travel / point_step))


def dense_configurations(
    names: Sequence[str], times: FloatArray, positions: FloatArray, levers: Levers,
    joint_step: float, point_step: float,
) -> Iterator[tuple[float, FloatArray]]:  # fmt: skip
    """``(t, positions)`` from the first stored point to the last, within both steps; the
    ``k``-th of ``n`` steps at share ``s = k / n`` is ``(1 - s) * start + s * end`` (one
    segment's steps computed at once, each entry by the same operations)."""
    yield float(times[0]), positions[0]
    for i in range(len(times) - 1):
        n = levers.steps(names, positions[i + 1] - positions[i], joint_step, point_step)
        s = np.arange(1, n + 1) / n
        rest = 1.0 - s
        steps = rest[:, None] * positions[i] + s[:, None] * positions[i + 1]
        yield from zip((rest * times[i] + s * times[i + 1]).tolist(), steps, strict=True)


def _radii(robot: RobotHandle, held: Mapping[str, str]) -> dict[str, float]:
    """Per link: how far its shapes (and what it holds) reach from its frame [m]."""
    world = robot.world
    raw = RawDistances(world)
    radius: dict[str, float] = {}
    links = raw.collision_links(robot.name)
    for link, box in zip(links, raw.link_bounds(robot.name, links), strict=True):
        radius[link] = _far_corner(world.link_pose(robot.name, link).position, box)
    for obj, link in held.items():
        parts = raw.collision_links(obj)
        origin = world.link_pose(robot.name, link).position
        for box in raw.link_bounds(obj, parts):
            radius[link] = max(radius.get(link, 0.0), _far_corner(origin, box))
    return radius


def _far_corner(origin: Sequence[float], box: tuple[Sequence[float], Sequence[float]]) -> float:
    low, high = np.asarray(box[0]), np.asarray(box[1])
    far = np.maximum(np.abs(low - origin), np.abs(high - origin))
    return float(np.linalg.norm(far))


def _reach_below(model: RobotModel, radius: Mapping[str, float]) -> dict[str, float]:
    """Per link: the farthest any point below it (itself included) can be from its frame."""
    children: dict[str, list[tuple[str, float]]] = {}
    for joint in model.joints.values():
        length = float(np.linalg.norm(joint.origin.position))
        if joint.type == "prismatic":
            length += max(abs(joint.lower or 0.0), abs(joint.upper or 0.0))
        children.setdefault(joint.parent, []).append((joint.child, length))
    reach: dict[str, float] = {}

    def down(link: str) -> float:
        below = [length + down(child) for child, length in children.get(link, [])]
        reach[link] = max([radius.get(link, 0.0), *below])
        return reach[link]

    down(model.root_link)
    return reach

"""Detours tried before planning: lift the tool, cross over at that height, lower it.

Most arm motions whose straight joint segment is blocked are blocked near an end: the
fingers sweep through the object they are about to grasp, a held mug is dragged through
the table it is put on, the forearm scrapes the table when the arm parks after placing.
Lifting the tool at the start, crossing at that height and lowering it at the goal clears
such obstacles. Each lift is made by one joint, the one that raises the tool most within
its limits (a shoulder, or the torso), linearised at that configuration; a last try shares
a higher lift between the two steepest joints, for an arm that turns its upper arm over
on the way (its hand sweeps far below the wrist). Every segment is
checked on the world like a straight motion, so a detour costs a few dozen checks where
planning costs a snapshot and thousands; one that fails leaves the planner to it. Nothing
is random: the same motion always gets the same detour.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.configuration_checker import ConfigurationChecker
from robocram.motion.joint_path import JointPath
from robocram.motion.joint_slots import JointSlots
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.robot_geometry import RobotGeometry
from robocram.motion.segment_check import CheckCounter, segment_free
from robocram.motion.travel_bound import TravelBound
from robocram.robots.lazy_library import LazyLibrary
from robocram.world import RobotHandle

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

DETOUR_LIFTS = (0.3, 0.5)  # [m] tool lifts tried, in order, each by one joint
SHARED_LIFT = 0.5  # [m] then this lift, shared by the two steepest joints
MIN_LIFT = 0.05  # [m] a joint that lifts the tool less than this makes no detour
MAX_TURN = 1.0  # [rad | m] the most a lift changes its joint
LIFT_STEPS = 4  # secant steps towards the lift
LIFT_TOLERANCE = 0.01  # [m] a lift this near the one asked for is taken
SLOPE_STEP = 1e-4  # [rad | m] finite difference of the tool's height per joint


@dataclass(frozen=True)
class ToolHeight:
    """The height [m] of an arm's tool over the robot's root link, as the motion's joints
    (the others as the robot stands) change."""

    geometry: RobotGeometry
    slots: JointSlots
    frame: int  # pinocchio frame of the tool

    @classmethod
    def of(cls, robot: RobotHandle, joints: Sequence[str]) -> ToolHeight | None:
        """The height of the tool of the arm moved by most of ``joints``; None if none is."""
        world = robot.world
        desc = robot.description
        arms = [arm for arm in desc.arms.values() if set(arm.joints) & set(joints)]
        if not arms:
            return None
        arm = max(arms, key=lambda arm: len(set(arm.joints) & set(joints)))
        geometry = desc.model.derived(RobotGeometry.of)
        kin = geometry.kinematics
        masters = {
            j: v for j, v in world.joint_states(robot.name).items()
            if kin.robot_model.joints[j].mimic is None
        }  # fmt: skip
        slots = JointSlots(kin, joints, kin.configuration(masters))
        return cls(geometry, slots, kin.frame_id(arm.tool_frame))

    def height(self, q: FloatArray) -> float:
        """The tool's height [m] over the root link at ``q``."""
        model, data = self.geometry.kinematics.model, self.geometry.data()
        pin.framesForwardKinematics(model, data, self.slots.full(q))
        return float(data.oMf[self.frame].translation[2])

    def raised(
        self,
        q: FloatArray,
        lift: float,
        limits: tuple[Sequence[float], Sequence[float]],
        joints: int = 1,
    ) -> FloatArray | None:
        """``q`` with the joint changed that lifts the tool most steeply: by ``lift`` [m],
        or as far as its limits and :data:`MAX_TURN` let it, if that is at least
        :data:`MIN_LIFT`; None when no joint can. With ``joints`` > 1, a lift one joint
        leaves short is carried on by the next steepest (a torso at its top, then the
        shoulder).
        """
        here = self.height(q)
        found = self._steepest(q, here, here + lift, limits, ())
        if found is None:
            return None
        moved, used = found[0], [found[1]]
        while len(used) < joints and here + lift - self.height(moved) > LIFT_TOLERANCE:
            more = self._steepest(moved, self.height(moved), here + lift, limits, used)
            if more is None:
                break
            moved = more[0]
            used.append(more[1])
        return moved

    def _steepest(
        self,
        q: FloatArray,
        here: float,
        target: float,
        limits: tuple[Sequence[float], Sequence[float]],
        used: Sequence[int],
    ) -> tuple[FloatArray, int] | None:
        """``q`` lifted towards ``target`` [m] by the steepest joint not ``used`` that
        lifts the tool at least :data:`MIN_LIFT` above ``here`` (its height at ``q``)."""
        slopes = []  # [m] per unit of each joint
        for i in range(len(q)):
            probe = q.copy()
            probe[i] += SLOPE_STEP
            slopes.append((self.height(probe) - here) / SLOPE_STEP)
        for i in sorted(range(len(q)), key=lambda i: -abs(slopes[i])):
            if abs(slopes[i]) < 1e-6:
                break
            if i in used:
                continue
            raised = self._lifted(q, i, target, slopes[i], limits)
            if self.height(raised) - here >= MIN_LIFT:
                return raised, i
        return None

    def _lifted(
        self,
        q: FloatArray,
        joint: int,
        target: float,
        slope: float,
        limits: tuple[Sequence[float], Sequence[float]],
    ) -> FloatArray:
        """``q`` with ``joint`` moved towards the tool height ``target`` [m] by a few
        secant steps from ``slope``, within its limits and :data:`MAX_TURN` of ``q``."""
        low = max(limits[0][joint], q[joint] - MAX_TURN)
        high = min(limits[1][joint], q[joint] + MAX_TURN)
        value, height = float(q[joint]), self.height(q)
        moved = q.copy()
        for _ in range(LIFT_STEPS):
            step = (target - height) / slope
            moved[joint] = float(np.clip(value + step, low, high))
            if abs(moved[joint] - value) < 1e-9:
                break
            now = self.height(moved)
            slope = (now - height) / (moved[joint] - value) if now != height else slope
            value, height = float(moved[joint]), now
            if abs(target - height) < LIFT_TOLERANCE or abs(slope) < 1e-6:
                break
        return moved


def detour_path(
    checker: ConfigurationChecker,
    start: Sequence[float],
    goal: Sequence[float],
    bound: TravelBound,
    limits: tuple[Sequence[float], Sequence[float]],
    height: ToolHeight,
    lifts: Sequence[float] = DETOUR_LIFTS,
    shared_lift: float | None = SHARED_LIFT,
) -> JointPath | None:
    """A free path start, start lifted, goal lifted, goal; None if there is none (or an
    end collides).

    ``limits`` are the joints' (lower, upper) bounds; the first lift of ``lifts`` [m]
    whose path is free is taken, each made by one joint; then ``shared_lift`` (None: not
    tried), made by two joints where one is not enough: an arm that must turn its upper
    arm over (a put-down reached from the other elbow branch) sweeps the hand well below
    the wrist, and a torso alone, at its top after a few centimetres, lifts it too little.
    """
    a, b = np.asarray(start, dtype=float), np.asarray(goal, dtype=float)
    counter = CheckCounter(checks=2)
    if not (checker.is_free(a) and checker.is_free(b)):
        return None
    tries = [(lift, 1) for lift in lifts]
    if shared_lift is not None:
        tries.append((shared_lift, 2))
    done: list[tuple[FloatArray, FloatArray]] = []
    for lift, joints in tries:
        up_a, up_b = height.raised(a, lift, limits, joints), height.raised(b, lift, limits, joints)
        if up_a is None or up_b is None or _tried(done, up_a, up_b):
            continue
        done.append((up_a, up_b))
        points = [a, up_a, up_b, b]
        counter.checks += 2
        if not (checker.is_free(up_a) and checker.is_free(up_b)):
            continue
        legs = zip(points, points[1:], strict=False)
        if all(segment_free(checker, p, q, bound, counter) for p, q in legs):
            waypoints = tuple(tuple(map(float, p)) for p in points)
            return JointPath(checker.joints, waypoints, "detour", counter.checks)
    return None


def _tried(done: list[tuple[FloatArray, FloatArray]], up_a: FloatArray, up_b: FloatArray) -> bool:
    """Whether these lifted ends were checked already (a joint at its limit lifts the same
    for every lift asked)."""
    return any(np.array_equal(a, up_a) and np.array_equal(b, up_b) for a, b in done)

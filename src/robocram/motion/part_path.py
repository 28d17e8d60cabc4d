"""How a hand holds a handle and the steps a part's joint moves in: shared by projection
and the ROS arms, so both open drawers and doors the same way.

The gripper takes the handle from the front: its approach axis along the handle frame's
-x (which points out of the front), rolled about that axis by one of :data:`ROLLS` (a bar
handle wants the fingers across it, and robots' hands differ); when no roll from the
front holds it, from above (:func:`from_above`, slanted first). The joint then moves in
steps of at most :data:`LINEAR_STEP` of the handle's travel, the tool put on the handle
at each.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

LINEAR_STEP = 0.02  # [m] of the handle's travel between IK checks
FRAME_OFF_FRONT = math.radians(45.0)  # [rad] a handle frame's x this far off the way out
PROBE = 1e-3  # [m | rad] joint step over which the handle's way out is measured
PRE_GRASP = 0.10  # [m] in front of the handle before and after holding it
BACK_OFF = (PRE_GRASP, PRE_GRASP / 2)  # [m] tried in turn when letting go of the handle
ROLLS = (math.pi / 2, -math.pi / 2, 0.0, math.pi)  # [rad] about the approach axis
PITCHES = (math.radians(45.0), math.pi / 2)  # [rad] a hold frame turned down, from above


def grasp_in_handle(axis_in_tool: np.ndarray, roll: float) -> Pose:
    """The tool pose in the handle frame: approach axis along the handle's -x, rolled."""
    into = np.array((-1.0, 0.0, 0.0))
    turn = np.cross(axis_in_tool, into)
    angle = math.atan2(float(np.linalg.norm(turn)), float(axis_in_tool @ into))
    if np.linalg.norm(turn) < 1e-9:
        turn = np.array((0.0, 0.0, 1.0))
    aligned = quat.from_axis_angle(tuple(turn / np.linalg.norm(turn)), angle)
    return Pose(orientation=quat.multiply(quat.from_axis_angle((1.0, 0.0, 0.0), roll), aligned))


def from_above(pull: Pose, pitch: float) -> Pose:
    """The hold frame ``pull`` (x out of the front, z up) turned about its y so that its
    x points ``pitch`` [rad] up: the hand comes down onto the handle, pointing down as
    much, and pulls it along the part's way out. Tried (:data:`PITCHES`) after every grasp
    from the front failed: Centauro's arms reach a drawer's handle, 0.58 m under its
    shoulders, only pointing down, and its ball hand fits between the handle and the
    counter's top over it only slanted."""
    return pull * Pose(orientation=quat.from_axis_angle((0.0, 1.0, 0.0), -pitch))


def handle_speed(world: World, part: str, joint: str, handle: str) -> float:
    """How far [m] the handle moves per unit of the joint [m | rad] near its current value."""
    start = world.joint_states(part)[joint]
    limits = world.bodies.joint_limits(part, joint)
    probe = 1e-3 if start + 1e-3 <= limits.upper else -1e-3
    before = world.link_pose(part, handle).position
    world.set_joint_states(part, {joint: start + probe})
    moved = math.dist(before, world.link_pose(part, handle).position) / abs(probe)
    world.set_joint_states(part, {joint: start})
    return max(moved, 1e-3)


def part_path(world: World, part: str, joint: str, handle: str, goal: float) -> list[float]:
    """The joint values from after the current one to ``goal`` inclusive, the handle
    moving at most :data:`LINEAR_STEP` between two."""
    start = world.joint_states(part)[joint]
    step = LINEAR_STEP / handle_speed(world, part, joint, handle)
    count = max(1, math.ceil(abs(goal - start) / step))
    return [start + (goal - start) * (i + 1) / count for i in range(count)]


def pull_frame(world: World, part: str, joint: str, handle: str) -> Pose:
    """The frame to hold the handle in, in the handle's frame: the handle's own, unless
    its x points more than :data:`FRAME_OFF_FRONT` off the way out of the front.

    Then (a URDF whose handle frames point into the cabinet) x is turned to where the
    handle goes as the joint opens, level, with z up: the hand still comes from the front.
    """
    start = world.joint_states(part)[joint]
    limits = world.bodies.joint_limits(part, joint)
    far = limits.upper if abs(limits.upper) >= abs(limits.lower) else limits.lower
    toward = math.copysign(PROBE, far)  # the joint's opening way
    sign = 1.0 if abs(start + toward) <= abs(far) else -1.0  # at its far limit: step back
    here = world.link_pose(part, handle)
    world.set_joint_states(part, {joint: start + sign * toward})
    there = world.link_pose(part, handle).position
    world.set_joint_states(part, {joint: start})
    out = np.array(there[:2]) - np.array(here.position[:2])
    norm = float(np.linalg.norm(out))
    x_axis = quat.rotate(here.orientation, (1.0, 0.0, 0.0))
    if norm < 1e-9:
        return Pose()
    out = sign * out / norm
    if float(out @ np.array(x_axis[:2])) >= math.cos(FRAME_OFF_FRONT):
        return Pose()
    yaw = math.atan2(float(out[1]), float(out[0]))
    level = quat.from_euler(0.0, 0.0, yaw)
    return Pose(orientation=quat.multiply(quat.conjugate(here.orientation), level))

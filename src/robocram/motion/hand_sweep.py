"""Holding a base drive that carries a hand in contact to the hand's bound.

A drive inside ``move_tcp`` (a planar arm reaches with its base: the Stretch, the HSR) lets
the hand's links through the base checker, so that the fingers may stay round what they
grasp. Letting them touch anything swept a Stretch's fingers 29 mm through the mug it had
just let go (issue 35). :func:`hand_breach` walks the drive's trajectory densely (no point of
the hand moves more than :data:`HAND_STEP` between two looks) and finds where a hand link
touches something other than what the hand acts on, or goes into it deeper than the bound
(the :class:`~robocram.motion.hand_contact.HandContact`, raised to the depth the drive
starts with).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from robocram.execution import checkpoint
from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.carried_joint import CarriedJoint
from robocram.motion.hand_contact import HandContact, hand_at_start
from robocram.motion.joint_trajectory import BASE_JOINTS, JointTrajectory
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle

HAND_STEP = 0.005  # [m] the most a point of the hand moves between two looks


@dataclass(frozen=True)
class HandBreach:
    """Where a drive takes the hand too far: the time [s], the link, what it touches, how
    deep [m] and the bound [m] (0 for what the hand may not touch at all)."""

    time: float
    link: str
    other: str
    depth: float
    bound: float


def hand_breach(
    robot: RobotHandle,
    trajectory: JointTrajectory,
    hand: HandContact,
    carried: Sequence[CarriedJoint] = (),
) -> HandBreach | None:
    """The first place ``trajectory`` (a base drive from where ``robot`` stands) takes the
    hand beyond ``hand``'s contact, or None; ``carried`` joints (a door the hand pulls
    round) move along in proportion to time. The robot and the joints are put back."""
    world = robot.world
    if trajectory.joint_names != BASE_JOINTS or len(trajectory.points) < 2:
        return None
    hand = hand_at_start(world, robot.name, hand) or hand
    rules = AllowedContacts.of(robot.description, ())
    links = sorted(link for link in hand.links if link in robot.body.link_index)
    start = world.pose(robot.name)
    reach = _hand_reach(robot, links, start)
    before = [(c.obj, c.joint, world.joint_states(c.obj)[c.joint]) for c in carried]
    duration = trajectory.duration
    try:
        for time, (x, y, yaw) in _dense(trajectory, reach):
            checkpoint()  # a stopped task ends the walk here
            world.set_pose(
                robot.name, Pose((x, y, start.position[2]), quat.from_euler(0.0, 0.0, yaw))
            )
            for c in carried:
                world.set_joint_states(c.obj, {c.joint: c.at(time / duration if duration else 1.0)})
            for link, obj, other_link, gap in world.contacts.link_distances(
                robot.name, distance=0.0, links=links
            ):
                if gap >= 0.0 or rules.allows(link, Other(obj.name, obj.type)):
                    continue
                named = f"{obj.name}/{other_link}" if len(obj.link_index) > 1 else obj.name
                bound = hand.depth if hand.covers(link, named) else 0.0
                if -gap > max(bound, 0.001):
                    return HandBreach(time, link, named, -gap, bound)
    finally:
        world.set_pose(robot.name, start)
        for part, joint, value in before:
            world.set_joint_states(part, {joint: value})
    return None


def _hand_reach(robot: RobotHandle, links: list[str], base: Pose) -> float:
    """[m] the farthest a point of the hand lies from the base's vertical axis."""
    world = robot.world
    radii = world.contacts.link_radii(robot.name)
    far = 0.0
    for link in links:
        x, y, _ = world.link_pose(robot.name, link).position
        far = max(
            far, math.hypot(x - base.position[0], y - base.position[1]) + radii.get(link, 0.0)
        )
    return far


def _dense(trajectory: JointTrajectory, reach: float) -> list[tuple[float, tuple[float, ...]]]:
    """The trajectory's base poses, filled in so that no point within ``reach`` [m] of the
    base's axis moves more than :data:`HAND_STEP` between two."""
    times = [p.time_from_start for p in trajectory.points]
    poses = np.array([p.positions for p in trajectory.points], dtype=float)
    found: list[tuple[float, tuple[float, ...]]] = [(times[0], tuple(poses[0]))]
    for k in range(1, len(poses)):
        a, b = poses[k - 1], poses[k]
        travel = math.hypot(b[0] - a[0], b[1] - a[1]) + reach * abs(b[2] - a[2])
        steps = max(1, math.ceil(travel / HAND_STEP))
        for s in range(1, steps + 1):
            f = s / steps
            found.append((times[k - 1] + f * (times[k] - times[k - 1]), tuple(a + f * (b - a))))
    return found

"""A held thing's contacts where a motion starts: kept, but no deeper than they start.

A motion may keep the contacts it starts with: a hand on a handle, a carton just gripped
where it stands on the table. Kept at any depth, a held thing could be pushed into what
it touched: the HSR's lift of a gripped milk carton turned it as it rose, and its bottom
edge went 1.06 mm into the table (the trace audit's bound is 1 mm). So a held thing's
start contact is a named contact bounded at the depth it starts with plus
:data:`DEEPEN` (:class:`~robocram.motion.contact_allowance.ContactAllowance`, as a tool's
contacts are), and the robot's own links' start contacts stay kept as they are (the hand's
contact with what it acts on has its own bound).
"""

from __future__ import annotations

from collections.abc import Collection

from robocram.motion.configuration_checker import LinkPair
from robocram.motion.contact_allowance import ContactAllowance
from robocram.world import RobotHandle

DEEPEN = 0.0005  # [m] a held thing's start contact may deepen by this (numerics)


def split_start_contacts(
    robot: RobotHandle, touching: Collection[LinkPair]
) -> tuple[list[LinkPair], list[ContactAllowance]]:
    """``touching`` (robot link or held thing, other) split into the pairs kept as they
    are (the robot's links') and a bounded contact per held thing's pair."""
    world = robot.world
    held = world.bodies.attachments(robot.name)
    kept: list[LinkPair] = []
    bounded: list[ContactAllowance] = []
    for mine, other in touching:
        if mine not in held:
            kept.append((mine, other))
            continue
        name, _, link = other.partition("/")
        points = world.contacts.contact_points(mine, name, None, link or None, 0.0)
        depth = max((-p.distance for p in points), default=0.0)
        bounded.append(ContactAllowance(mine, other, max(depth, 0.0) + DEEPEN))
    return kept, bounded

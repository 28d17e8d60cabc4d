"""The room a palm hand's curled fingers leave a bar held on its palm, measured on their
surfaces.

A palm hand (Armar6's, the Hey5's: ``grasping.palm``) holds a bar on its palm, the
fingers curled round it. Its fingers' joint frames say nothing of the room between their
surfaces and the bar: Armar6's first phalanges swing into the bar as the hand opens from a
fist (at the 0.231 of the way open that the frames gave a 3 cm gap, 13 mm in the 2 cm
bar) and out of it only when nearly straight. So the room is measured on the fingers'
collision shapes, by PyBullet: a probe bar (a box of the bar's cross-section, as long as
the handle, across the fingers where the hold puts the bar's middle) is put at the hand,
the fingers are set part of the way open, and the probe's closest points to the fingers'
links give how far it clears them. The probe and the fingers are put back: the world is
as it was. A hand and a bar give one answer, kept on the robot's model.

A palm that is a thin plate (Armar6's stand-in, shaped from its finger row) puts the bar
against the knuckles, where the fist's stand-in phalanges lie in it: no curl clears it.
Then the bar may be held further out along the fingers (:func:`fingers_shift`), in the
curl, where the hand held it while its palm box reached 7 cm out.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np

from robocram.grasping.palm import Palm, palm_of
from robocram.projection.gripper import gripper_of
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotModel
from robocram.tf import Pose
from robocram.tf import quaternion as quat

PROBE = "bar_room_probe"  # the probe bar's name while it is in the world
SCAN = 16  # steps from the fist to the open hand, searched for where the bar first meets
# the fingers (they may clear it again nearly straight: Armar6's)
BISECTIONS = 10  # halvings of a step: 1/16384 of the full opening
REACH = 0.05  # [m] the farthest clearance read: more is room enough for any bar
SHIFT_STEP = 0.005  # [m] steps out along the fingers for a bar the fist has no room round


class _Fractions:
    """The fractions found per (arm, width, length, shift) for one robot model."""

    def __init__(self, model: RobotModel) -> None:
        self.found: dict[tuple[str, float, float, float], float | None] = {}


def room_at(
    robot: ProjectedRobot, arm: str, fraction: float, width: float, length: float
) -> float | None:
    """[m] the widest bar (square, centred where ``arm``'s palm hold puts the middle of a bar
    ``width`` thick) that ``arm``'s fingers ``fraction`` of the way open clear: ``width``
    plus twice the probe's clearance (negative: the fingers lie in it); None for a hand
    that is no palm hand."""
    palm = palm_of(robot.description, arm)
    if palm is None:
        return None
    with _probe(robot, arm, palm, width, length):
        return width + 2 * _clearance(robot, arm, fraction)


def curled_fraction(
    robot: ProjectedRobot, arm: str, width: float, length: float, shift: float = 0.0
) -> float | None:
    """The widest fraction open (0 a fist) up to which ``arm``'s curled fingers clear a bar
    ``width`` [m] thick and ``length`` [m] long held on its palm (``shift`` [m] further out
    along the fingers); None when no palm hand, when even the fist leaves it no room, or
    when the fingers clear it all the way open (nothing to narrow). Kept per model, arm
    and bar."""
    if palm_of(robot.description, arm) is None:
        return None
    model = robot.description.model
    key = (arm, round(width, 4), round(length, 4), round(shift, 4))
    kept = model.derived(_Fractions).found if model is not None else {}
    if key not in kept:
        kept[key] = _search(robot, arm, width, length, shift)
    return kept[key]


def fingers_shift(robot: ProjectedRobot, arm: str, width: float, length: float) -> float | None:
    """[m] how far out along ``arm``'s fingers from its palm hold a bar ``width`` thick is
    held where the palm hold leaves a fist no room round it: the nearest of
    :data:`SHIFT_STEP` steps, up to the fingers' reach, at which the curled fingers clear
    it (:func:`curled_fraction` there); None when the palm hold has room, or none has."""
    palm = palm_of(robot.description, arm)
    if palm is None:
        return None
    with _probe(robot, arm, palm, width, length):
        if _clearance(robot, arm, 0.0) >= 0.0:
            return None  # the palm hold has room: :func:`curled_fraction` says how much
    for step in range(1, int(palm.reach / SHIFT_STEP) + 1):
        shift = step * SHIFT_STEP
        if curled_fraction(robot, arm, width, length, shift) is not None:
            return shift
    return None


def _search(
    robot: ProjectedRobot, arm: str, width: float, length: float, shift: float = 0.0
) -> float | None:
    """:func:`curled_fraction` measured: the first of :data:`SCAN` steps from the fist at
    which the fingers meet the probe, then bisection back to where they just clear it."""
    palm = palm_of(robot.description, arm)
    assert palm is not None  # asked by curled_fraction only
    with _probe(robot, arm, palm, width, length, shift):
        if _clearance(robot, arm, 0.0) < 0.0:
            return None
        fits = 0.0
        for step in range(1, SCAN + 1):
            meets = step / SCAN
            if _clearance(robot, arm, meets) < 0.0:
                break
            fits = meets
        else:
            return None
        for _ in range(BISECTIONS):
            middle = (fits + meets) / 2
            if _clearance(robot, arm, middle) >= 0.0:
                fits = middle
            else:
                meets = middle
        return fits


@contextmanager
def _probe(
    robot: ProjectedRobot, arm: str, palm: Palm, width: float, length: float, shift: float = 0.0
) -> Iterator[None]:
    """The probe bar at ``arm``'s hand (``shift`` [m] out along the fingers from the palm
    hold) for the block, the fingers put back after it."""
    world = robot.world
    gripper = gripper_of(robot, arm)
    states = world.joint_states(robot.name)
    before = {j: states[j] for j in gripper.names}
    x, y, z = (
        h + shift * a
        for h, a in zip(palm.holding(width / 2, width / 2, flat=False), palm.along, strict=True)
    )
    held = (x, y, z)
    axes = quat.from_matrix(np.column_stack([palm.curl, palm.along, palm.across]))
    tool = world.link_pose(robot.name, robot.arm(arm).tool_frame)
    world.add_box(PROBE, (width, width, length), tool * Pose(held, axes))
    try:
        yield
    finally:
        world.remove(PROBE)
        world.set_joint_states(robot.name, before)


def _clearance(robot: ProjectedRobot, arm: str, fraction: float) -> float:
    """[m] how far ``arm``'s fingers ``fraction`` open clear the probe (negative: depth in
    it); :data:`REACH` when farther."""
    world = robot.world
    world.set_joint_states(robot.name, gripper_of(robot, arm).at(fraction))
    fingers = robot.arm(arm).gripper_links
    points = world.contacts.links_contact_points(robot.name, fingers, PROBE, distance=REACH)
    return min((p.distance for p in points), default=REACH)

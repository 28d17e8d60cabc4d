"""A hand opened only as wide as a handle's bar needs, for taking it when fully open fails.

A fully open many-fingered hand (TALOS's, Armar6's) spreads its fingers far beyond a 2 cm
bar: from above or from the front they go into the drawer's front or the counter's top
before the palm reaches the bar. Opened just wider than the bar, the fingers stay near
it. The opening is the bar's thickness (the smallest extent of the handle link's bounds)
plus :data:`BAR_MARGIN`, as the gripper description measures its widest gap
(``robots.derived_values.widest_opening``) at each fraction of the way open; the fraction
is found by bisection.

Last of all, a palm hand whose fist has no room round the bar held on its palm (a thin
palm plate puts the bar at the knuckles) takes it further out along its fingers, curled
round it (:func:`fingers_hold`): after every other hold, so a hand that holds today
holds as before.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import replace

from robocram.execution.failures import GripperPathBlocked
from robocram.grasping.palm import palm_of
from robocram.kinematics import PlanarBase, solve_ik
from robocram.kinematics.ik_options import IKOptions
from robocram.projection.bar_room import curled_fraction, fingers_shift
from robocram.projection.collision_mode import collision_check, putting_back_once
from robocram.projection.gripper import gripper_of, set_gripper
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots.derived_values import widest_opening
from robocram.robots.gripper import GripperJoint
from robocram.tf import Pose

BAR_MARGIN = 0.01  # [m] wider than the bar: room for the fingers' aim (5 mm either side)
NARROWEST_SLACK = 0.005  # [m] a hand that opens no narrower than this beyond the width has none
BISECTIONS = 12  # halvings of the fraction: 1/4096 of the full opening
REACH = PlanarBase(0.5, 0.5, 1.0)  # [m, m, rad] the base's move to get the hand to the handle
REACH_RESTARTS = 10  # IK restarts of the look before a narrower hand moves (30 cost Armar6's
# drawer 0.36 s of looks, 10: 0.16 s, and it still opens)


def bar_thickness(robot: ProjectedRobot, part: str, handle: str) -> float:
    """[m] the handle's thinnest extent: the bar's thickness the fingers close across."""
    return bar_extents(robot, part, handle)[0]


def bar_extents(robot: ProjectedRobot, part: str, handle: str) -> tuple[float, float]:
    """[m] the handle's thinnest and longest extents: the bar's thickness and length."""
    low, high = robot.world.contacts.link_aabb(part, handle)
    extents = [h - lo for lo, h in zip(low, high, strict=True)]
    return min(extents), max(extents)


def gap_at(robot: ProjectedRobot, arm: str, fraction: float) -> float:
    """[m] the widest gap between ``arm``'s fingers ``fraction`` of the way open (0 closed,
    1 open), measured as the description's ``max_opening`` is; 0 where none opens."""
    gripper = gripper_of(robot, arm)
    part_way = tuple(
        GripperJoint(j.name, open=j.closed + fraction * (j.open - j.closed), closed=j.closed)
        for j in gripper.joints
    )
    spec = robot.arm(arm)
    fingers = tuple(spec.gripper_links)
    model = robot.description.model
    gap = widest_opening(model, replace(gripper, joints=part_way), fingers)
    return 0.0 if gap is None else gap


def bar_fraction(robot: ProjectedRobot, arm: str, width: float) -> float | None:
    """The fraction of the way open (0 closed, 1 open) at which ``arm``'s fingers are
    ``width`` [m] apart; None when fully open is no wider (nothing to narrow), when the
    fingers open no narrower than well beyond it, or the hand holds by suction."""
    gripper = gripper_of(robot, arm)
    if gripper.is_suction or gap_at(robot, arm, 1.0) <= width:
        return None
    narrow, wide = 0.0, 1.0
    for _ in range(BISECTIONS):
        middle = (narrow + wide) / 2
        if gap_at(robot, arm, middle) >= width:
            wide = middle
        else:
            narrow = middle
    if gap_at(robot, arm, wide) > width + NARROWEST_SLACK:
        return None  # its fingers stop farther apart (Kevin's 59 mm): no narrower hand
    return wide


def bar_opening(robot: ProjectedRobot, arm: str, part: str, handle: str) -> float | None:
    """The fraction to open ``arm``'s hand to for ``handle``'s bar: its thickness plus
    :data:`BAR_MARGIN`; None when the full opening is no wider. A palm hand's is measured
    on its fingers' surfaces round the bar held on its palm (:mod:`bar_room`): the widest
    opening at which its curled fingers still clear the bar with the margin."""
    thickness, length = bar_extents(robot, part, handle)
    if palm_of(robot.description, arm) is not None:
        return curled_fraction(robot, arm, thickness + BAR_MARGIN, length)
    return bar_fraction(robot, arm, thickness + BAR_MARGIN)


def fingers_hold(
    robot: ProjectedRobot, arm: str, part: str, handle: str
) -> tuple[Pose, float] | None:
    """Where a palm hand whose fist has no room round ``handle``'s bar on its palm holds it
    in its fingers: the tool's shift (tool frame) from the palm hold and the fraction
    open; None for any other hand, or where no place along the fingers has room."""
    palm = palm_of(robot.description, arm)
    if palm is None:
        return None
    thickness, length = bar_extents(robot, part, handle)
    width = thickness + BAR_MARGIN
    shift = fingers_shift(robot, arm, width, length)
    if shift is None:
        return None
    fraction = curled_fraction(robot, arm, width, length, shift)
    if fraction is None:
        return None
    x, y, z = (-shift * a for a in palm.along)  # the tool back: the bar further out
    return Pose((x, y, z)), fraction


def set_open(robot: ProjectedRobot, arm: str, fraction: float) -> None:
    """Open (or close) ``arm``'s fingers to ``fraction`` of the way open.

    Raises:
        GripperPathBlocked: the fingers' way runs into something; they did not move.
    """
    gripper = gripper_of(robot, arm)
    set_gripper(robot, arm, gripper.at(fraction)[gripper.names[0]])


def open_to(robot: ProjectedRobot, arm: str, fraction: float) -> bool:
    """:func:`set_open` where the hand is; False if the fingers are blocked there."""
    try:
        set_open(robot, arm, fraction)
    except GripperPathBlocked:
        return False
    return True


def narrowing_frees(
    robot: ProjectedRobot, arm: str, at_handle: Pose, touching: str, fraction: float
) -> bool:
    """Whether IK holds ``arm``'s tool at ``at_handle`` (map) with its fingers ``fraction``
    open and not with them fully open: the open fingers were what refused the hold. Asked
    before any motion, so a narrower hand moves only where it makes the difference (a hold
    refused for another cause moves nothing more)."""
    return _reaches(robot, arm, at_handle, touching, fraction) and not _reaches(
        robot, arm, at_handle, touching, 1.0
    )


def _reaches(
    robot: ProjectedRobot, arm: str, at_handle: Pose, touching: str, fraction: float
) -> bool:
    """Whether IK puts the tool at ``at_handle``, the fingers ``fraction`` open, the hand
    touching ``touching`` only, the base free within :data:`REACH` (the fingers are set to
    look, and put back)."""
    world = robot.world
    gripper = gripper_of(robot, arm)
    states = world.joint_states(robot.name)
    before = {j: states[j] for j in gripper.names}
    check = collision_check(robot, arm, "allow_hand", touching)
    try:
        world.set_joint_states(robot.name, gripper.at(fraction))
        in_base = robot.base_pose().inverse() * at_handle
        options = IKOptions(base=REACH, max_restarts=REACH_RESTARTS)
        with robot.ik_lock, putting_back_once(check):
            seed = world.joint_states(robot.name)
            result = solve_ik(
                robot.description, arm, in_base, seed=seed, options=options, collision_check=check
            )
    finally:
        world.set_joint_states(robot.name, before)
    return result.success


def hold_tries(
    robot: ProjectedRobot,
    arm: str,
    handle: tuple[str, str],
    frames: list[tuple[float, Pose]],
    rolls: Callable[[], list[float]],
    untouched: Callable[[], bool],
    grasp: Callable[[float], Pose],
) -> Iterator[tuple[float, Pose, float, float | None]]:
    """The holds to try on ``handle`` (part, link), as (pitch, frame, roll, opening): each
    frame (``frames``: pitch, frame) with each of ``rolls()`` and the hand fully open
    (opening None), as ever; then, only if ``untouched()`` (no hold moved the part) and the
    hand opens wider than the bar needs, each again with the hand opened just that wide
    (:func:`bar_opening`), where that frees the hold (:func:`narrowing_frees`;
    ``grasp(roll)``: the tool in the frame); then a palm hand with no room round the bar
    on its palm holds it in its fingers (:func:`fingers_hold`: the frame moved so), where
    IK reaches that: untouched, or where the open hand's holds moved the part only part
    of the way (Armar6's open hand pushed its drawer from 0.4 m open to 0.038 m, and none
    took it further: the hold out along its fingers opened it from shut)."""
    for pitch, frame in frames:
        for roll in rolls():
            yield pitch, frame, roll, None
    part_way = not untouched()
    if part_way and palm_of(robot.description, arm) is None:
        return
    part, link = handle
    opening = bar_opening(robot, arm, part, link)
    if opening is not None:
        if part_way:
            return
        for pitch, frame in frames:
            for roll in rolls():
                at_handle = robot.world.link_pose(part, link) * frame * grasp(roll)
                if narrowing_frees(robot, arm, at_handle, f"{part}/{link}", opening):
                    yield pitch, frame, roll, opening
        return
    found = fingers_hold(robot, arm, part, link)
    if found is None:
        return
    shift, fraction = found
    for pitch, frame in frames:
        for roll in rolls():
            held = grasp(roll)
            moved = frame * held * shift * held.inverse()  # the frame's axes kept
            at_handle = robot.world.link_pose(part, link) * moved * held
            if _reaches(robot, arm, at_handle, f"{part}/{link}", fraction):
                yield pitch, moved, roll, fraction

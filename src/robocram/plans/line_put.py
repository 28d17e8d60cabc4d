"""Put a held thing into a shelf from a stand on its approach line: the reverse of a
pick from a line stand (``line_stand/5``, :func:`pick_object._line_stand`).

The drafted Stretch's arm reaches sideways along a level telescope from a base that
cannot slide. Its usual puts into the fridge fail: every stand that holds the milk over
its spot as the hand holds it collides with the fridge's body, door or walls, and the
carry height over the spot is 2.5 cm beyond the lift's top. From a stand whose heading
lays the telescope on the line the hand came in on, the telescope alone carries the
thing in along the shelf's depth, :data:`RISE` over its spot (not a carry height: that
is out of reach), lets it down, and the open hand draws back along the same line.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterable, Sequence

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import (
    ManipulationLowLevelFailure,
    NavigationLowLevelFailure,
    PlanFailure,
)
from robocram.knowledge.reasoning_predicates import LINE_STAND
from robocram.logic import UnknownPredicateError, current_kb
from robocram.plans.basic_actions import look_ahead, navigate
from robocram.plans.grasp_failures import PlacingFailed
from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import GRASPING, Held
from robocram.plans.place_object import PLACE_GAP, SETTLE, arm_now, settled
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat

OUT = 0.3  # [m] back along the approach line the hand holds the thing before it goes in
# (the pick's pre-grasp, 10 cm, and its draw back, 20 cm)
FREE = 0.15  # [m] of telescope out (past its margin) with the thing at ``out``: drawn
# in, the hand met the mast
RISE = 0.02  # [m] over its put the thing is carried in (a shelf's edge lies lower)
LEAD = 0.6  # [m] ahead of or behind a line stand, on its heading, the thing is readied


def _move(arm: str, pose: Pose, **mode: str) -> None:
    target = PoseStamped.from_pose("map", pose)
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=target), **mode))


def _up(pose: Pose, rise: float) -> Pose:
    x, y, z = pose.position
    return Pose((x, y, z + rise), pose.orientation)


def _back(pose: Pose, wrist_in_tool: tuple[float, float, float], distance: float) -> Pose:
    """``pose`` (a tool pose) moved ``distance`` towards its wrist, level."""
    d = quat.rotate(pose.orientation, wrist_in_tool)
    level = math.hypot(d[0], d[1]) or 1.0
    x, y, z = pose.position
    return Pose((x + distance * d[0] / level, y + distance * d[1] / level, z), pose.orientation)


def _wrist_in_tool(held: Held) -> tuple[float, float, float] | None:
    """The direction from the tool to its wrist, in the tool frame (None: no wrist)."""
    wrist = current_robot().end_effector_link(held.arm)
    if wrist is None:
        return None
    p = transform_pose(PoseStamped(wrist), held.tool_frame).pose.position
    norm = math.sqrt(sum(c * c for c in p)) or 1.0
    return (p[0] / norm, p[1] / norm, p[2] / norm)


def _stand(held: Held, out: Pose, tool: Pose) -> PoseStamped | None:
    try:
        row = LINE_STAND.first(
            current_kb(), robot=current_robot().name, arm=held.arm,
            out=PoseStamped.from_pose("map", out), grasp=PoseStamped.from_pose("map", tool),
        )  # fmt: skip
    except UnknownPredicateError:
        return None
    return None if row is None else row.stand


def _telescopic(held: Held, wrist: tuple[float, float, float]) -> bool:
    """Whether ``held.arm`` reaches along a level telescope: ``line_stand/5`` answers for
    a short level way in from where its tool is (an arm without one is answered at once,
    before any other spot is sampled)."""
    tool = transform_pose(PoseStamped(held.tool_frame), "map").pose
    return _stand(held, _back(tool, wrist, 0.1), tool) is not None


def line_put(held: Held, spots: Iterable[Pose], depths: Sequence[float]) -> Pose | None:
    """Put ``held`` at the first of ``spots`` (map poses of the thing's frame on a shelf)
    reached from a line stand, the hand coming in level along one of ``depths`` (map
    headings [rad], the shelf's depth first), the thing turned about the vertical to
    suit; the spot, or None where no arm has a level telescope, no line stand was found,
    or every try failed with the thing still held (the arm then back as it held it).

    Raises:
        PlacingFailed: the thing was let go but did not rest where it was put.
    """
    wrist = _wrist_in_tool(held)
    if wrist is None or not _telescopic(held, wrist):
        return None
    heading = transform_pose(PoseStamped(held.object_name), "map").pose.orientation
    start = arm_now(held.arm)
    tool_now = transform_pose(PoseStamped(held.tool_frame), "map").pose
    ahead = quat.rotate(tool_now.orientation, wrist)  # towards the wrist: back
    coming = math.atan2(-ahead[1], -ahead[0])  # the heading the hand comes in along now
    for spot in spots:
        x, y, z = spot.position
        for depth in depths:
            turn = depth - coming
            put = Pose((x, y, z + PLACE_GAP), quat.multiply(quat.from_euler(0, 0, turn), heading))
            tool = put * held.object_in_tool.inverse()
            high = _up(tool, RISE)
            out = _back(high, wrist, OUT)
            stand = _stand(held, _back(high, wrist, OUT + FREE), high)
            if stand is None:
                continue
            if _put_from(held, stand, (out, high, tool), put, wrist):
                return spot
    _restore(held.arm, start)
    return None


def _restore(arm: str, joints: list[list[object]]) -> None:
    """Take ``arm`` back to ``joints`` (as it held the thing before the first try), best
    effort: readied for a line stand, the thing held out to the side blocked every drive
    back to the table."""
    if not joints:
        return
    with contextlib.suppress(ManipulationLowLevelFailure, NavigationLowLevelFailure):
        perform(a.motion(type="moving-arm-joints", arm=arm, configuration=joints, **GRASPING))


def _ready(held: Held, stand: PoseStamped, out: Pose, mode: dict[str, str]) -> None:
    """Hold the thing where it is to be at ``out`` once the base stands at ``stand``,
    from a stand :data:`LEAD` ahead of or behind it on its heading: as the arm held it
    (out to the side from the last try) the drive's goal put it in the fridge's body, and
    at the table the arm had no room to take it there.

    Raises:
        ManipulationLowLevelFailure: neither lead stand let the arm take it there.
        NavigationLowLevelFailure: neither lead stand was reached.
    """
    yaw = 2.0 * math.atan2(stand.orientation[2], stand.orientation[3])
    for sign in (1.0, -1.0):
        x, y, _ = stand.position
        lead = Pose(
            (x + sign * LEAD * math.cos(yaw), y + sign * LEAD * math.sin(yaw), 0.0),
            stand.orientation,
        )
        try:
            navigate(PoseStamped.from_pose("map", lead))
            look_ahead()  # a head turned down meets the lift carriage high up
            _move(held.arm, lead * stand.pose.inverse() * out, **mode)
            return
        except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
            if sign < 0.0:
                raise  # the other lead stand failed before


def _put_from(
    held: Held,
    stand: PoseStamped,
    way: tuple[Pose, Pose, Pose],
    put: Pose,
    wrist: tuple[float, float, float],
) -> bool:
    """Whether the thing went down at ``put`` from ``stand``: the tool in from ``out``
    to ``high`` over ``tool`` (``way``), down, let go, and the open hand back along the
    line :data:`OUT` from its put."""
    out, high, tool = way
    mode = {**GRASPING, "touching": held.object_name}
    try:
        _ready(held, stand, out, mode)
        navigate(stand)
    except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
        return False  # the hand never went in
    try:
        _move(held.arm, out, **mode)
        _move(held.arm, high, **mode)
        _move(held.arm, tool, **mode)
    except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
        with contextlib.suppress(ManipulationLowLevelFailure, NavigationLowLevelFailure):
            _move(held.arm, out, **mode)
        return False
    perform(a.motion(type="opening", gripper=held.arm))
    try:
        _move(held.arm, _back(tool, wrist, OUT), **mode)
    except PlanFailure as failure:
        raise PlacingFailed(
            f"{held.object_name!r} was let go but the {held.arm} hand could not draw back",
            object_name=held.object_name,
            target=put,
            causes=[failure],
        ) from failure
    problem = settled(held.object_name, put, SETTLE)
    if problem is not None:
        raise PlacingFailed(
            f"{held.object_name!r} was let go at {put} but {problem}",
            object_name=held.object_name,
            target=put,
            causes=[],
        )
    return True

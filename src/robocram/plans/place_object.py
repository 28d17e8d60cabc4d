"""Put a held object down: over the target keeping the grasp, lower, open, retreat, check.

The target is the pose the object's frame is to have, resting on a surface (what an ``on``
location designator with ``for_`` the object gives; for a mug, whose frame is at its
bottom, the surface point itself); the object is let go :data:`PLACE_GAP` above it. The tool targets
follow from the grasp the object is held with (the object's pose in the tool frame), so
any grasp places the same way. The object comes down from 10 cm above (5 cm, or straight
to its place, at the edge of the arm's reach). If the arm cannot put it down turned as
asked, the object is turned about the vertical by a quarter, a half and three quarters in
turn. Let go, the hand backs off towards the wrist (10 cm, or 5), or else the arm parks, or
else it goes back out the way it came in.
Then the world is simulated briefly (where the KB has one) and the object must rest where
it was put.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Sequence

from robocram.designators import LocationDesignator, ObjectDesignator, a
from robocram.execution import perform
from robocram.execution.failures import (
    ManipulationLowLevelFailure,
    NavigationLowLevelFailure,
    PlanFailure,
)
from robocram.knowledge.robot_predicates import ARM_JOINTS, GRIPPER_JOINT
from robocram.knowledge.world_predicates import ATTACHED, SETTLING
from robocram.logic import UnknownPredicateError, current_kb
from robocram.plans.basic_actions import park_arms
from robocram.plans.errors import PlanSetupError
from robocram.plans.grasp_failures import PlacingFailed
from robocram.plans.known_robot import KnownRobot, current_robot
from robocram.plans.pick_object import GRASPING, Held, object_name
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat

PLACE_GAP = 0.005  # [m] the object is let go this far above its target (a location's
# target already rests a gap above the surface; a bare pose may be the surface itself; at
# 2 mm the HSR's hand, backing off, knocked 2 of 50 mugs off the table)
CARRY_HEIGHTS = (0.10, 0.05)  # [m] the object comes in from this far above, first that works
RETREATS = (0.10, 0.05)  # [m] the open hand backs off this far towards the wrist, or less
OUT_OPENING = 0.25  # of the way from the grip to open: the hand goes out the way it came in
# so narrowed where its open fingers met the counter's top (Boxy's bowl rim, seed 33)
SETTLE = 0.15  # [s] simulated at most after letting go: the 7 mm drop takes 0.04 s
MAX_SETTLE_DROP = 0.03  # [m] it may sink this much (the gap, contact) and still rest
MOVED = 1e-3  # [m] a hand moved less than this by a failed put is where it started
BASE_TURNED = 1e-3  # [rad] a base turned less than this still stands where it stood
TURNS = (0.0, math.pi / 2, -math.pi / 2, math.pi)  # [rad] object turns tried in order


def held_object(obj: Held | ObjectDesignator | str, arm: str | None) -> Held:
    """``obj`` if already a :class:`Held`, else the grasp it is held with now."""
    if isinstance(obj, Held):
        return obj
    robot, name = current_robot(), object_name(obj)
    kb = current_kb()
    for choice in robot.grasping_arms():
        link = robot.end_effector_link(choice)
        if link is None or (arm is not None and choice != arm):
            continue
        if ATTACHED.holds(kb, object=name, robot=robot.name, link=link):
            frame = robot.tool_frame(choice)
            here = transform_pose(PoseStamped(frame), "map")
            held = transform_pose(PoseStamped(name), frame).pose
            return Held(choice, "unknown", name, frame, here, here, held)
    raise PlanSetupError(f"{robot.name} holds no {name!r}" + (f" in its {arm} hand" if arm else ""))


def _shifted(pose: Pose, dx: float, dy: float, dz: float) -> Pose:
    x, y, z = pose.position
    return Pose((x + dx, y + dy, z + dz), pose.orientation)


def _object_targets(target: PoseStamped | Pose | LocationDesignator) -> list[Pose]:
    """Poses of the object's frame (map) just above the target, one per turn."""
    where = target.reference() if isinstance(target, LocationDesignator) else target
    if isinstance(where, Pose):
        where = PoseStamped.from_pose("map", where)  # a location's pose is in the map
    if not isinstance(where, PoseStamped):
        raise PlanSetupError(
            f"place_object's target is a PoseStamped, a Pose (map) or a location designator, "
            f"got {where!r}"
        )
    spot = _shifted(transform_pose(where, "map").pose, 0.0, 0.0, PLACE_GAP)
    turned = []
    for turn in TURNS:
        q = quat.multiply(quat.from_euler(0.0, 0.0, turn), spot.orientation)
        turned.append(Pose(spot.position, q))
    return turned


def _move(arm: str, pose: Pose, **mode: str) -> None:
    target = PoseStamped.from_pose("map", pose)
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=target), **mode))


def _retreat(robot: KnownRobot, held: Held) -> None:
    """Back the open hand off towards the wrist; park the arm if it cannot."""
    wrist_link = robot.end_effector_link(held.arm)
    tool = transform_pose(PoseStamped(held.tool_frame), "map").pose
    back = (0.0, 0.0, 1.0)
    if wrist_link is not None:
        wrist = transform_pose(PoseStamped(wrist_link), "map").pose.position
        d = [w - t for w, t in zip(wrist, tool.position, strict=True)]
        norm = math.sqrt(sum(c * c for c in d)) or 1.0
        back = (d[0] / norm, d[1] / norm, d[2] / norm)
    for distance in RETREATS:
        try:
            back_off = _shifted(tool, *(distance * c for c in back))
            _move(held.arm, back_off, **GRASPING, touching=held.object_name)
            return
        except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
            continue  # a planar arm backs off with its base: a drive may be blocked too
    park_arms(held.arm)


def _back_to(held: Held, start: Pose, joints: list[list[object]], base: Pose) -> None:
    """Take the hand, still holding the object, back to ``start`` where a put failed in
    every turn: each turn's approach may have got it over the spot, deep in an open drawer
    under the counter's top, and the robot would then drive to its next stand with it
    there (the PR2's every drive was blocked at its start). The arm goes back to the
    ``joints`` it had there, not just the tool pose: IK may reach that pose on another
    branch (the Donbot's UR5 came back with its wrist low over the table's top, and every
    motion from its next stand started blocked). Only while the base stands where it stood
    (``base``): after a turn moved it, those joints put the hand elsewhere (the PR2's,
    0.2 m off in the stove's drawer, and the clearing then left a bowl on the table), so
    the hand goes back to ``start`` itself. Best effort: where the way back is blocked,
    the hand stays and the drive says so."""
    here = transform_pose(PoseStamped(held.tool_frame), "map").pose
    if math.dist(here.position, start.position) < MOVED:
        return
    now = transform_pose(PoseStamped(current_robot().base_frame()), "map").pose
    stood = math.dist(now.position, base.position) < MOVED and (
        quat.angle_between(now.orientation, base.orientation) < BASE_TURNED
    )
    with contextlib.suppress(ManipulationLowLevelFailure, NavigationLowLevelFailure):
        if joints and stood:
            perform(
                a.motion(
                    type="moving-arm-joints", arm=held.arm, configuration=joints,
                    **GRASPING, touching=held.object_name,
                )
            )  # fmt: skip
            here = transform_pose(PoseStamped(held.tool_frame), "map").pose
            if math.dist(here.position, start.position) < MOVED:
                return
    with contextlib.suppress(ManipulationLowLevelFailure, NavigationLowLevelFailure):
        _move(held.arm, start, **GRASPING, touching=held.object_name)


def settled(name: str, put: Pose, seconds: float) -> str | None:
    """Why the object does not rest where it was put within ``seconds`` [s], or None.

    The world is simulated until the object rests (``settle/3``: it stopped moving between
    two looks, see :mod:`robocram.world.settling`) or ``seconds`` have passed. An object
    let go 7 mm above its support lands within the fifth look and rests by the sixth or
    seventh, 12 to 14 physics steps of the 36 in :data:`SETTLE`: the shorter the drop, the
    sooner it rests, so the location's pose lies on the object's true bottom (not its
    Bullet bounds, a few mm lower).
    """
    if seconds <= 0.0:
        return None
    try:
        if not SETTLING.holds(current_kb(), object=name, seconds=float(seconds)):
            return None
    except UnknownPredicateError:
        return None  # no simulated world to ask (a real robot)
    now = transform_pose(PoseStamped(name), "map").pose
    drop = put.position[2] - now.position[2]
    if drop > MAX_SETTLE_DROP or now.distance_to(put) > MAX_SETTLE_DROP + 0.02:
        return f"it moved {now.distance_to(put):.3f} m after letting go (fell or slid)"
    return None


def _out_the_way_in(
    held: Held,
    way_in: list[Pose],
    grip: float | None = None,
    joints_in: Sequence[list[list[object]]] = (),
) -> bool:
    """Whether the open hand went back out through ``way_in`` (map tool poses, the last
    the nearest the put), as a last resort after backing off towards the wrist and parking
    failed: Boxy let a bowl go by its rim low in an open drawer, its hand had come in on
    another IK branch, and neither way out was free under the counter's top (seed 17).
    The hand may brush anything on its way back (within the grasp's bound): the open
    fingers touched the top's underside. Where that way is blocked too (seed 33: a new IK
    solution for a pose it came in from swings the hand into the top), the hand narrows
    to :data:`OUT_OPENING` of the way from ``grip`` (its master finger joint as it held
    the thing) to open, a little wider than it came in, and the arm goes back through
    the joint values it came in by (``joints_in``, the first where it started), last
    first, under ``allow_hand`` (the fingers came in brushing the top). Projection takes
    each leg back along the way the arm came (``projection/arm_ways.py``): seed 33's came
    round the top's edge 0.5 mm clear, the straight joint way back dips 18 mm into it.
    False where it did not get out (or had not come in from anywhere)."""
    if _back_through(held, way_in, **GRASPING):
        return True
    if grip is None or not joints_in or not _narrowed(held.arm, grip):
        return False
    for states in reversed(joints_in):
        try:
            perform(
                a.motion(type="moving-arm-joints", arm=held.arm, configuration=states, **GRASPING)
            )
        except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
            return False
    return True


def arm_now(arm: str) -> list[list[object]]:
    """``arm``'s joint values now, as a configuration to move to (empty: none known)."""
    robot = current_robot()
    row = ARM_JOINTS.first(current_kb(), robot=robot.name, arm=arm)
    if row is None:
        return []
    values = [(joint, robot.joint_position(joint)) for joint in row.joints]
    if any(value is None for _, value in values):
        return []
    return [[joint, value] for joint, value in values]


def _back_through(held: Held, way_in: list[Pose], **mode: str) -> bool:
    """Whether the hand went back through ``way_in``'s poses, the nearest first, those
    it is not at already."""
    here = transform_pose(PoseStamped(held.tool_frame), "map").pose
    back = [pose for pose in reversed(way_in) if math.dist(here.position, pose.position) >= MOVED]
    for pose in back:
        try:
            _move(held.arm, pose, **mode)
        except (ManipulationLowLevelFailure, NavigationLowLevelFailure):
            return False
    return bool(back)


def _grip(arm: str) -> float | None:
    """The value of ``arm``'s master finger joint now (None: no finger joint)."""
    robot = current_robot()
    row = GRIPPER_JOINT.first(current_kb(), robot=robot.name, arm=arm)
    return robot.joint_position(row.joint) if row is not None else None


def _narrowed(arm: str, grip: float) -> bool:
    """Whether ``arm``'s open hand closed to :data:`OUT_OPENING` of the way from ``grip``
    back to where it is open now."""
    opened = _grip(arm)
    if opened is None or abs(opened - grip) < 1e-6:
        return False
    angle = grip + OUT_OPENING * (opened - grip)
    try:
        perform(a.motion(type="moving-gripper-joint", gripper=arm, joint_angle=angle))
    except PlanFailure:
        return False
    return True


def _put_down(robot: KnownRobot, held: Held, put: Pose) -> None:
    tool = put * held.object_in_tool.inverse()
    way_in = [transform_pose(PoseStamped(held.tool_frame), "map").pose]
    joints_in = [arm_now(held.arm)]
    for height in CARRY_HEIGHTS:
        try:
            above = _shifted(tool, 0.0, 0.0, height)
            _move(held.arm, above, **GRASPING, touching=held.object_name)
            way_in.append(above)
            joints_in.append(arm_now(held.arm))
            break
        except ManipulationLowLevelFailure:
            continue  # at the edge of its reach the arm comes in lower
    _move(held.arm, tool, **GRASPING, touching=held.object_name)
    grip = _grip(held.arm)
    perform(a.motion(type="opening", gripper=held.arm))
    try:
        _retreat(robot, held)
    except ManipulationLowLevelFailure as failure:  # let go already: no other turn to try
        if _out_the_way_in(held, way_in, grip, [c for c in joints_in if c]):
            return
        raise PlacingFailed(
            f"{held.object_name!r} was let go but the {held.arm} hand could not back off",
            object_name=held.object_name,
            target=put,
            causes=[failure],
        ) from failure


def place_object(
    object: Held | ObjectDesignator | str,  # noqa: A002 - CRAM's key
    target: PoseStamped | Pose | LocationDesignator,
    arm: str | None = None,
    settle: float = SETTLE,
) -> PoseStamped:
    """Put the held ``object`` down with its frame at ``target``; return where it rests.

    ``target`` may be a location designator (its first pose is taken) or a map pose. The
    returned pose is in ``map``. ``settle`` [s] is simulated after letting go to check the
    object rests (0: no check).

    Raises:
        PlacingFailed: no turn of the object could be put down there, or it did not rest
            (``causes`` holds each try's failure).
        PlanSetupError: the robot does not hold the object.
    """
    robot = current_robot()
    held = held_object(object, arm)
    start = transform_pose(PoseStamped(held.tool_frame), "map").pose
    start_joints = arm_now(held.arm)
    start_base = transform_pose(PoseStamped(robot.base_frame()), "map").pose
    causes: list[Exception] = []
    for put in _object_targets(target):
        try:
            _put_down(robot, held, put)
        except ManipulationLowLevelFailure as failure:
            causes.append(failure)
            continue
        problem = settled(held.object_name, put, settle)
        if problem is not None:
            raise PlacingFailed(
                f"{held.object_name!r} was let go at {target} but {problem}",
                object_name=held.object_name,
                target=target,
                causes=causes,
            )
        return transform_pose(PoseStamped(held.object_name), "map")
    _back_to(held, start, start_joints, start_base)
    raise PlacingFailed(
        f"{robot.name} could not put {held.object_name!r} down at {target} in any of "
        f"{len(TURNS)} turns (causes: "
        + ", ".join(sorted({type(c).__name__ for c in causes}))
        + ")",
        object_name=held.object_name,
        target=target,
        causes=causes,
    )

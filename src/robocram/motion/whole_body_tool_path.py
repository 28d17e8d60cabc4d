"""A tool path followed by base and arm together: one checked, timed whole-body trajectory.

An arm that reaches with its base (the HSR's five joints, the Stretch's telescope) cannot
keep a sponge flat along a strip or a knife on its sawing line by itself. Here each step
of the tool point's curve is solved for base and arm at once
(:func:`~robocram.kinematics.whole_body_track.track_whole_body`: a differential base only
drives along its heading) and the trajectory's joints are the base's ``x``, ``y``, ``yaw``
in map followed by the arm's, timed under every limit of both. Between waypoints base and
arm move linearly in those joints, which is exactly how the virtual base chain moves.

Every step and the segment to it are checked on the world over the whole robot (the base
moves every link: :class:`~robocram.motion.whole_body_scene.WholeBodyScene`); a segment is
checked at the resolution a bound on its travel gives, the base's turn levered by the
farthest point of the robot and what it holds. The arm is walked against the robot's own
body as in any tool path. As there, only the named contacts are allowed, each bounded.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterator, Mapping, Sequence

import numpy as np

from robocram.kinematics import IKResult, PlanarBase
from robocram.kinematics.planar_base import BASE_X_JOINT, BASE_Y_JOINT, BASE_YAW_JOINT
from robocram.kinematics.whole_body_track import track_whole_body
from robocram.motion.arm_motion import MotionSettings
from robocram.motion.carried_joint import CarriedJoint
from robocram.motion.cartesian_path import JUMP_THRESHOLD
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.hand_contact import HandContact, hand_at_start
from robocram.motion.held_start_contacts import split_start_contacts
from robocram.motion.joint_path import JointPath
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.segment_check import CheckCounter, segment_free
from robocram.motion.tool_path import (
    AT_TCP,
    DEFAULT_SETTINGS,
    TOOL_PATH_KIND,
    ToolPathMotion,
    cut_apart,
    timed_tool_path,
    tool_targets,
)
from robocram.motion.travel_bound import TravelBound
from robocram.motion.whole_body_scene import WholeBodyScene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle


def plan_whole_body_tool_path(
    robot: RobotHandle,
    arm: str,
    path_in_base: Sequence[Pose],
    *,
    point_in_tcp: Pose = AT_TCP,
    contacts: Collection[ContactAllowance] = (),
    settings: MotionSettings = DEFAULT_SETTINGS,
    base: PlanarBase | None = None,
    hand: HandContact | None = None,
    allowed_links: Collection[str] = (),
    kind: str = TOOL_PATH_KIND,
    goal: Mapping[str, float] | None = None,
    carried: Sequence[CarriedJoint] = (),
    keep_touching: bool = True,
) -> ToolPathMotion:
    """Follow the tool point through ``path_in_base`` (poses in the robot's root link where
    it stands now) with base and arm, as far as it can be followed.

    ``base`` bounds how far the base may go (default :class:`PlanarBase`'s travel); the
    ``hand`` may touch what it acts on within its bound (a door's handle it pulls round),
    ``allowed_links`` anything; the trajectory is of ``kind`` and stores what it allows.
    ``goal``: a solution at the path's end that base and arm should share the motion as
    (:func:`~robocram.kinematics.whole_body_track.track_whole_body`). ``carried``: parts
    the hand moves along (a door's joint), checked where the tool takes them.
    A held thing touching something at the start may stay no deeper; the robot's own
    links touching something (beyond the hand's bound) may move off it, or, with
    ``keep_touching`` False, the path is refused where it starts (a door's step: a link
    left in the door would be dragged deeper as base and arm pull it round).

    Raises:
        MotionInputError: the path is empty or has more steps than a trajectory holds.
    """
    world = robot.world
    targets = tool_targets(robot, arm, path_in_base, point_in_tcp, "a whole-body tool path")
    desc = robot.description
    joints = tuple(desc.arms[arm].joints)
    current = world.joint_states(robot.name)
    start = world.pose(robot.name)
    hand = hand_at_start(world, robot.name, hand)
    scene, touching = _scene(
        robot, joints, tuple(contacts), tuple(allowed_links), hand, tuple(carried)
    )
    arm_bound = TravelBound.of(robot, joints)
    if touching and not keep_touching:
        named = ", ".join(f"{a} touches {b}" for a, b in touching[:2])
        waypoints, levers = [tuple(scene.now().tolist())], 0.0
        stopped = f"the robot starts in contact ({named})"
    else:
        answers = track_whole_body(desc, arm, targets, current, base or PlanarBase(), goal)
        waypoints, levers, stopped = _follow(scene, arm_bound, start, joints, answers)
    fraction = (len(waypoints) - 1) / len(targets)
    path = JointPath(scene.joints, tuple(waypoints), "whole-body", len(waypoints))
    path, fraction, stopped = cut_apart(robot, path, fraction, stopped, joints)
    bound = TravelBound(scene.joints, np.concatenate(([1.0, 1.0, levers], arm_bound.lever)))
    held = hand.allowances() if hand is not None else ()
    allowed = (*contacts, *held)
    timed = timed_tool_path(robot, path, fraction, scene, bound, settings, kind, allowed)
    return ToolPathMotion(timed, fraction, stopped)


def _scene(
    robot: RobotHandle,
    joints: tuple[str, ...],
    contacts: tuple[ContactAllowance, ...],
    allowed_links: tuple[str, ...],
    hand: HandContact | None,
    carried: tuple[CarriedJoint, ...],
) -> tuple[WholeBodyScene, list[LinkPair]]:
    """The world as the checker, the named contacts and the hand bounded; the robot's own
    links' contacts at the start (beyond those bounds) allowed to end, a held thing's no
    deeper than it starts. Also those links' start contacts."""
    scene = WholeBodyScene(robot, joints, (), contacts, allowed_links, hand, carried)
    with scene.posed():
        touching = scene.colliding(scene.now())
        if not touching:
            return scene, []
        kept, bounded = split_start_contacts(robot, touching)
    return WholeBodyScene(
        robot, joints, kept, (*contacts, *bounded), allowed_links, hand, carried
    ), kept


def _follow(
    scene: WholeBodyScene,
    arm_bound: TravelBound,
    start: Pose,
    joints: tuple[str, ...],
    answers: Iterator[IKResult],
) -> tuple[list[tuple[float, ...]], float, str]:
    """The waypoints reached (map base, then arm), the largest turn lever [m] on the way,
    and why it stopped ("" at the end)."""
    x0, y0, _ = start.position
    yaw0 = quat.to_euler(start.orientation)[2]
    c, s = math.cos(yaw0), math.sin(yaw0)
    q = scene.now()
    waypoints = [tuple(q.tolist())]
    counter = CheckCounter()
    lever = 0.0
    with scene.posed():
        for k, result in enumerate(answers):
            if not result.success:
                return (
                    waypoints,
                    lever,
                    f"IK found no whole-body solution {k + 1} steps along the path",
                )
            v = result.joint_positions
            bx, by = v.get(BASE_X_JOINT, 0.0), v.get(BASE_Y_JOINT, 0.0)
            nxt: FloatArray = np.array(
                [x0 + c * bx - s * by, y0 + s * bx + c * by, yaw0 + v.get(BASE_YAW_JOINT, 0.0),
                 *(v[j] for j in joints)]
            )  # fmt: skip
            jump = float(np.abs(nxt - q).max())
            if jump > JUMP_THRESHOLD:
                return waypoints, lever, f"a joint jumps {jump:.2f} between steps {k} and {k + 1}"
            bound = scene.bound(q, nxt, arm_bound)
            lever = max(lever, float(bound.lever[2]))
            pairs = scene.colliding(nxt)
            if pairs or not segment_free(scene, q, nxt, bound, counter):
                link, other = pairs[0] if pairs else ("the robot", "something on the way")
                return waypoints, lever, f"{link} hits {other} {k + 1} steps along the path"
            q = nxt
            waypoints.append(tuple(q.tolist()))
    return waypoints, lever, ""

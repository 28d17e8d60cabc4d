"""Opening and closing articulated parts (drawers, doors) in projection.

The gripper takes the handle from the front (its approach axis along the handle frame's
-x, which points out of the front), closes, and the part's joint is then moved in small
steps; at each step the tool is put, by IK, where the handle has gone, so the tool
follows the drawer's line or the door's arc. A step the arm cannot follow ends the motion
with the part where the arm last held it. Whatever rests in the moving link (a bowl in a
drawer) is attached to it for the motion, so it moves along.

The grasp's roll about the approach axis is not known in advance (a bar handle wants the
fingers across it, and robots' hands differ), so the rolls in ``motion.part_path.ROLLS``
are tried in order, each with the whole path, from the same start; when none held it
from the front, they are tried again from above.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial

import numpy as np

from robocram.execution import TaskStopped, checkpoint
from robocram.execution.failures import (
    EnvironmentManipulationImpossible,
    GripperPathBlocked,
    ManipulationGoalNotReached,
    ManipulationPathBlocked,
    ManipulationPoseUnreachable,
    NavigationLowLevelFailure,
    NavigationPoseUnreachable,
)
from robocram.grasping import palm_hold
from robocram.kinematics import PlanarBase, forward_kinematics
from robocram.motion import CarriedJoint
from robocram.motion.part_path import (
    BACK_OFF,
    PRE_GRASP,
    ROLLS,
    grasp_in_handle,
    part_path,
)
from robocram.projection.arm import move_tcp
from robocram.projection.bar_opening import hold_tries, open_to, set_open
from robocram.projection.errors import ProjectionError
from robocram.projection.gripper import close_gripper, open_gripper
from robocram.projection.handle_holds import hold_frames, remember_pitch
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.navigation import drive
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat

LET_GO_RESTARTS = 8  # IK restarts per backing-off try: it is best effort
RESTING = 0.005  # [m] objects this close to the moving link move with it
HOLD_MODE = "allow_hand"  # the fingers close around the handle
STEP_HALVINGS = 2  # a step the hand cannot follow is tried in halves, then quarters
STEP_TRAVEL = PlanarBase(0.15, 0.15, 0.5)  # [m, m, rad] the base's move per step of the arc
REACH_TRAVEL = PlanarBase(0.5, 0.5, 1.0)  # [m, m, rad] to get the hand before the handle
HANDLE_HALF_WIDTH = 0.01  # [m] a palm hand holds a handle as a bar this thick (the kitchen's: 2 cm)
RELEASE_STEPS = 8  # steps a part is taken back to where the fingers can open to let go


@dataclass(frozen=True)
class ArticulationResult:
    """What moved: the part's joint from ``start`` to ``reached`` [m | rad], what rode along."""

    joint: str
    start: float
    reached: float
    roll: float  # [rad] the grasp roll about the approach axis that held the path
    carried: tuple[str, ...]


def approach_axis(robot: ProjectedRobot, arm: str) -> np.ndarray:
    """The unit axis, in the tool frame, from the wrist towards the tool frame."""
    spec = robot.arm(arm)
    wrist = forward_kinematics(robot.description, {}, spec.end_effector_link)
    tool = forward_kinematics(robot.description, {}, spec.tool_frame)
    axis = -np.asarray((tool.inverse() * wrist).position, float)
    norm = float(np.linalg.norm(axis))
    if norm < 1e-6 and spec.gripper is not None and spec.gripper.is_suction:
        return np.array((1.0, 0.0, 0.0))  # a bare flange holds with its face: the tool's x
    if norm < 1e-6:
        raise ProjectionError(
            f"{robot.name}'s {arm} tool frame sits on its wrist; give the arm a tool frame "
            "in front of its end effector link so the approach axis is known"
        )
    return axis / norm


def resting_in(robot: ProjectedRobot, part: str, link: str) -> list[str]:
    """Free objects resting in or on ``link`` of ``part`` (not held by anything)."""
    world = robot.world
    out = []
    for obj in world.objects():
        if obj.is_static or obj.name in (part, robot.name) or world.bodies.attached_to(obj):
            continue
        if world.contacts.contact_points(obj, part, link_b=link, distance=RESTING):
            out.append(obj.name)
    return out


@dataclass(frozen=True)
class _Hold:
    """How the tool holds a part's handle while its joint moves."""

    part: str
    joint: str
    handle: str
    grasp: Pose
    pull: Pose


def _follow(
    robot: ProjectedRobot,
    arm: str,
    part: str,
    joint: str,
    handle: str,
    grasp: Pose,
    path: list[float],
    pull: Pose,
) -> float:
    """Move the joint along ``path`` with the tool on the handle; return the last value held.

    A step the hand cannot follow is tried again in halves (:data:`STEP_HALVINGS` times):
    where the base drives along, the handle moves in proportion to the drive's time, and a
    shorter step keeps the hand nearer its bounded contact on the handle. The steps after
    one that needed halves start at its size (a door's arc that wants them keeps wanting
    them), so each costs one try, not one failure per coarser size first."""
    hold = _Hold(part, joint, handle, grasp, pull)
    held = robot.world.joint_states(part)[joint]
    halving = 0
    for value in path:
        while True:
            steps = 2**halving
            done = held
            for k in range(1, steps + 1):
                checkpoint()  # a stopped task ends here, holding the handle at the last step
                goal = held + (value - held) * k / steps
                if not _step(robot, arm, hold, done, goal):
                    break
                done = goal
            if done == value:
                break
            if done != held:
                return done  # part of the way: the halves after it were out of reach
            if halving == STEP_HALVINGS:
                return held
            halving += 1
        held = value
    return held


def _straight_only(robot: ProjectedRobot) -> ProjectedRobot:
    """``robot`` with motions that do not plan round obstacles (a blocked one fails at
    once): letting go part of the way, a hand that cannot back off straight stays at the
    handle, where the next roll takes it anyway."""
    return replace(robot, motion=replace(robot.motion, plan=False))


def _step(robot: ProjectedRobot, arm: str, hold: _Hold, held: float, value: float) -> bool:
    """Move the joint from ``held`` to ``value`` with the tool on the handle; whether the
    hand followed (if not, the joint is back at ``held``)."""
    world = robot.world
    part, joint, handle = hold.part, hold.joint, hold.handle
    tool = robot.arm(arm).tool_frame
    begin = world.link_pose(robot.name, tool).position
    world.set_joint_states(part, {joint: value})
    goal = world.link_pose(part, handle) * hold.pull * hold.grasp
    # the hand moves it: where the tool has got to on its way, the part has too
    robot.carried[:] = [CarriedJoint(part, joint, held, value, tool, (begin, goal.position))]
    try:
        move_tcp(
            robot, arm, goal, HOLD_MODE, move_base=True, base_travel=STEP_TRAVEL,
            touching=f"{part}/{handle}", explain=False,
        )  # fmt: skip
    except (ManipulationPoseUnreachable, ManipulationGoalNotReached, NavigationLowLevelFailure):
        world.set_joint_states(part, {joint: held})
        return False
    except TaskStopped:  # stopped inside IK: the hand did not follow, undo the step
        world.set_joint_states(part, {joint: held})
        raise
    finally:
        robot.carried.clear()
    return True


def moving_link(robot: ProjectedRobot, part: str, joint: str) -> str:
    """The link ``joint`` of ``part`` moves (its child)."""
    body = robot.world.object(part)
    index = body.joint_index[joint]
    return next(name for name, i in body.link_index.items() if i == index)


def _take_handle(
    robot: ProjectedRobot,
    arm: str,
    part: str,
    handle: str,
    grasp: Pose,
    pull: Pose,
    opening: float | None = None,
) -> bool:
    """Open the gripper (fully, or ``opening`` of the way: :mod:`bar_opening`), come from
    the front, close it on the handle; False if unreachable.

    Fingers that cannot open where the hand is (under a counter's top) open in front of
    the handle.
    """
    world = robot.world
    held = world.link_pose(part, handle) * pull
    at_handle = held * grasp
    in_front = held * Pose((PRE_GRASP, 0.0, 0.0)) * grasp
    try:
        opened = _opened(robot, arm) if opening is None else open_to(robot, arm, opening)
        move_tcp(robot, arm, in_front, move_base=True, base_travel=REACH_TRAVEL, explain=False)
        if not opened:
            if opening is None:
                open_gripper(robot, arm)
            else:
                set_open(robot, arm, opening)
        checkpoint()
        move_tcp(
            robot, arm, at_handle, HOLD_MODE, move_base=True, base_travel=STEP_TRAVEL,
            touching=f"{part}/{handle}", explain=False,
        )  # fmt: skip
    except (
        ManipulationPoseUnreachable,
        ManipulationGoalNotReached,
        NavigationLowLevelFailure,
        GripperPathBlocked,
    ):
        return False
    close_gripper(robot, arm)
    return True


def _opened(robot: ProjectedRobot, arm: str) -> bool:
    """Open the gripper where the hand is; False if the fingers are blocked there."""
    try:
        open_gripper(robot, arm)
    except GripperPathBlocked:
        return False
    return True


def rolls_for(robot: ProjectedRobot, arm: str, part: str, handle: str) -> list[float]:
    """The grasp rolls to try on ``handle``: the one that last held it all the way first
    (a drawer is closed with the roll that opened it), then the one that last held any
    handle with ``arm`` (a kitchen's drawers have the same handles), then :data:`ROLLS`."""
    known = (robot.held_rolls.get((part, handle)), robot.held_rolls.get(("", arm)))
    return list(dict.fromkeys([*(r for r in known if r is not None), *ROLLS]))


def move_part(
    robot: ProjectedRobot, arm: str, part: str, joint: str, handle: str, goal: float
) -> ArticulationResult:
    """Hold ``handle`` with ``arm`` and move ``joint`` of ``part`` to ``goal`` [m | rad].

    A roll that moves the part only part of the way lets go there, and the next roll goes
    on from where it is (a door too wide open for one grasp is finished with another).

    Raises:
        ProjectionError: ``goal`` is outside the joint's limits.
        EnvironmentManipulationImpossible: no grasp roll lets the arm follow the handle all
            the way; the robot and the part are back where they started, as far as
            checked motions took them back (never set there).
        TaskStopped: the caller's task was stopped; the joint stays at the last step
            reached and nothing rides along any more.
    """
    world = robot.world
    limits = world.bodies.joint_limits(part, joint)
    if not limits.lower - 1e-9 <= goal <= limits.upper + 1e-9:
        raise ProjectionError(
            f"goal {goal:.3f} of {part}'s joint {joint!r} is outside its limits "
            f"[{limits.lower:.3f}, {limits.upper:.3f}]; ask for a value within them"
        )
    start = world.joint_states(part)[joint]
    palm = palm_hold(robot.description, arm, HANDLE_HALF_WIDTH)
    axis = approach_axis(robot, arm) if palm is None else np.asarray(palm[0])
    frames = hold_frames(robot, arm, part, joint, handle)
    first = _RobotAt.now(robot)
    riders = resting_in(robot, part, moving_link(robot, part, joint))
    for name in riders:
        world.attach(name, part, moving_link(robot, part, joint))
    moved: _Held | None = None  # the last roll that moved the part
    try:
        for pitch, pull, roll, opening in hold_tries(
            robot,
            arm,
            (part, handle),
            frames,
            partial(rolls_for, robot, arm, part, handle),  # read per pitch
            lambda: moved is None,  # noqa: B023
            lambda roll: _holding(axis, roll, palm),
        ):  # ``moved`` read as the tries go: the narrower hand only if nothing moved it
            checkpoint()
            grasp = _holding(axis, roll, palm)
            held = _Held(arm, part, joint, handle, grasp, pull, opening)
            here, now = _RobotAt.now(robot), world.joint_states(part)[joint]
            reached = _try_roll(robot, held, goal)
            if abs(reached - goal) <= 1e-9:
                robot.held_rolls[(part, handle)] = robot.held_rolls[("", arm)] = roll
                remember_pitch(robot, part, handle, pitch)
                return ArticulationResult(joint, start, reached, roll, tuple(riders))
            if abs(reached - now) > 1e-9:  # part of the way: let go, the next roll goes on
                opened = _released(robot, held, now)
                _let_go(_straight_only(robot), arm, part, handle, held.grasp, pull, opened)
                moved = held
            else:
                _back_to_start(robot, held, now, here.base, here.joints)
        if moved is not None:
            _undo(robot, moved, start, first)
    finally:
        for name in riders:
            world.detach(name)
    raise EnvironmentManipulationImpossible(
        f"{robot.name}'s {arm} arm cannot hold {handle!r} while {joint!r} moves from "
        f"{start:.3f} to {goal:.3f} with any grasp roll, from the front or from above "
        "(what to add: a wrist that turns the hand onto the bar, or a stand nearer it)",
        environment_part=joint,
        action="opening" if goal > start else "closing",
        reached=world.joint_states(part)[joint],
    )


def _holding(axis: np.ndarray, roll: float, palm: tuple[Vector3, Vector3] | None) -> Pose:
    """The tool pose in the handle frame for ``roll``; a palm hand (``palm``: its approach
    and where it holds a bar, tool frame) with the bar on its palm, the fingers round it."""
    pose = grasp_in_handle(axis, roll)
    if palm is None:
        return pose
    x, y, z = quat.rotate(pose.orientation, palm[1])
    return Pose((-x, -y, -z), pose.orientation)


def _try_roll(robot: ProjectedRobot, held: _Held, goal: float) -> float:
    """Take the handle with ``held``'s grasp and follow it towards ``goal``; the joint
    value reached (let go of when it is the goal, still held otherwise)."""
    world = robot.world
    start = world.joint_states(held.part)[held.joint]
    if not _take_handle(
        robot, held.arm, held.part, held.handle, held.grasp, held.pull, held.opening
    ):
        return start
    path = part_path(world, held.part, held.joint, held.handle, goal)
    reached = _follow(
        robot, held.arm, held.part, held.joint, held.handle, held.grasp, path, held.pull
    )
    if abs(reached - goal) <= 1e-9:
        _let_go(robot, held.arm, held.part, held.handle, held.grasp, held.pull)
    return reached


def _released(robot: ProjectedRobot, held: _Held, start: float) -> bool:
    """Open the gripper where a roll stopped part of the way; where the fingers cannot
    open (a wrist flexed far puts them into the forearm), take the part back towards
    ``start``, holding it, up to :data:`RELEASE_STEPS` steps, until they can. Whether they
    opened. Fingers left closed round a handle could neither back off nor let the next
    roll's approach drive the base away without going into the handle (issue 35)."""
    if _opened(robot, held.arm):
        return True
    world = robot.world
    hold = _Hold(held.part, held.joint, held.handle, held.grasp, held.pull)
    now = world.joint_states(held.part)[held.joint]
    back = part_path(world, held.part, held.joint, held.handle, start)
    for value in back[:RELEASE_STEPS]:
        if not _step(robot, held.arm, hold, now, value):
            return False
        now = value
        if _opened(robot, held.arm):
            return True
    return False


@dataclass(frozen=True)
class _RobotAt:
    """Where the robot stood and how its joints were (mimic joints left out: they follow
    their masters when those are set back)."""

    base: Pose
    joints: dict[str, float]

    @classmethod
    def now(cls, robot: ProjectedRobot) -> _RobotAt:
        model = robot.description.model
        joints = robot.world.joint_states(robot.name)
        kept = {j: v for j, v in joints.items() if model.joints[j].mimic is None}
        return cls(robot.base_pose(), kept)


def _undo(robot: ProjectedRobot, moved: _Held, start: float, first: _RobotAt) -> None:
    """After every roll failed: take the handle again with the last roll that moved the
    part, take it back to ``start`` and the robot to ``first``, as far as motions get
    (where the hand cannot take the handle again, the part stays where it was left)."""
    if _take_handle(
        robot, moved.arm, moved.part, moved.handle, moved.grasp, moved.pull, moved.opening
    ):
        _back_to_start(robot, moved, start, first.base, first.joints)


@dataclass(frozen=True)
class _Held:
    """How a roll holds the part: the arm, the part's joint and handle, the grasp."""

    arm: str
    part: str
    joint: str
    handle: str
    grasp: Pose
    pull: Pose
    opening: float | None = None  # [0-1] the hand opened only this far (a bar's width)


def _back_to_start(
    robot: ProjectedRobot,
    held: _Held,
    start: float,
    base_start: Pose,
    robot_start: dict[str, float],
) -> None:
    """After a grasp roll that did not hold all the way: the part and the robot back where
    they started, by motions, for the next roll. A part the roll had moved is taken back
    holding its handle, the hand lets go, the joints and the base go back along checked
    trajectories. Where any of that is blocked, the robot and the part stay where the
    motions got them, and the next roll starts from there: setting them back was a jump
    no robot can make (Boxy's breakfast: 11, at the fridge's door)."""
    world = robot.world
    arm, part, joint = held.arm, held.part, held.joint
    try:
        if abs(world.joint_states(part)[joint] - start) > 1e-9:
            back = part_path(world, part, joint, held.handle, start)
            _follow(robot, arm, part, joint, held.handle, held.grasp, back, held.pull)
            _let_go(robot, arm, part, held.handle, held.grasp, held.pull)  # where it got to
        else:
            _opened(robot, arm)
        moved = {
            j: v for j, v in robot_start.items()
            if abs(world.joint_states(robot.name)[j] - v) > 1e-9
        }  # fmt: skip
        if moved:
            move_along_checked(
                robot, moved, kind="arm", what=f"{robot.name}'s way back from {part}", plan=True
            )  # fmt: skip
        if robot.base_pose().distance_to(base_start) > 1e-6:
            drive(robot, base_start)
    except (
        ManipulationPathBlocked,
        NavigationPoseUnreachable,
        GripperPathBlocked,
        EnvironmentManipulationImpossible,
    ):
        pass


def _let_go(
    robot: ProjectedRobot,
    arm: str,
    part: str,
    handle: str,
    grasp: Pose,
    pull: Pose,
    opened: bool | None = None,
) -> None:
    """Open the gripper (unless ``opened`` says whether it was) and back the tool off the
    handle along its approach axis.

    A wide-open door can leave no room to back off the whole way: shorter moves are
    tried, and if none fits the open hand stays at the handle (the part is where asked).
    Fingers that cannot open at the handle (a drawer under a counter's top) open once the
    hand has backed off, if they can there.
    """
    opened = _opened(robot, arm) if opened is None else opened
    world = robot.world
    for distance in BACK_OFF:
        back = world.link_pose(part, handle) * pull * Pose((distance, 0.0, 0.0)) * grasp
        try:
            move_tcp(
                robot, arm, back, HOLD_MODE, move_base=True, max_restarts=LET_GO_RESTARTS,
                touching=f"{part}/{handle}", explain=False,
            )  # fmt: skip
        except (ManipulationPoseUnreachable, ManipulationGoalNotReached, NavigationLowLevelFailure):
            continue  # a door wide open can leave the base no room to back off either
        if not opened:
            _opened(robot, arm)
        return

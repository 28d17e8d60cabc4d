"""The ``reachable`` validator: a stand is taken if the task there will work from it.

To pick an object up, the pick plan's grasps must work (:func:`reach_to_pick`); to put
what the robot holds down at a target, the place plan's tool poses must
(:func:`reach_to_place`); a robot with empty hands reaching a target point only needs
the tool over it from above (``validators.reach_point``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from robocram.costmaps.cost_layer import LocationQuery
from robocram.costmaps.grasps import grasp_point
from robocram.costmaps.pick_reach import PickTarget, pick_targets, touched_objects
from robocram.costmaps.place_reach import held_objects, place_targets
from robocram.costmaps.reachability_map import ReachabilityMaps
from robocram.costmaps.validators import (
    IK_RESTARTS,
    STAND_IK_RESTARTS,
    Reach,
    hopeful_arms,
    placed,
    query_robot,
    reach_point,
    solve_at_stand,
)
from robocram.grasping import hand_of
from robocram.kinematics import BaseMotion, IKOptions, IKResult, solve_ik
from robocram.robots import RobotDescription
from robocram.tf import Pose, PoseStamped, Vector3
from robocram.world import RobotObject, World, WorldObject

PALM_IK_RESTARTS = 5  # per grasp of a palm hand when judging a stand (see _restarts)


def reach_to_pick(
    world: World,
    robot: RobotObject,
    obj: WorldObject,
    base: Pose,
    arm: str | None = None,
    maps: ReachabilityMaps | None = None,
    restarts: int = IK_RESTARTS,
    memo: dict[Any, Any] | None = None,
    touched: set[str] | None = None,
) -> Reach | None:
    """The first grasp the pick plan will try that works from ``base``, or None.

    The grasps are the grasp model's (``pick_reach.pick_targets``), in the pick's order;
    one works if IK reaches its pre-grasp and then, from there, its grasp (as the pick
    moves), nothing but the floor touches the robot at the pre-grasp, and only the hand
    touches at the grasp.

    Which grasp is tried first does not change the answer (the pick tries them all), so
    with a ``memo`` (one resolution: stand after stand) grasps that worked before go first
    and those that failed last. ``touched`` gathers the objects grasps that reached collided
    with (what blocks the stand, when none works).
    """
    seed = world.joint_states(robot)
    memo = {} if memo is None else memo
    key = ("grasp_point", obj.name, world.pose(obj))  # the object stays put meanwhile
    point = memo.get(key)
    if point is None:
        point = memo[key] = grasp_point(world, obj)
    for name in hopeful_arms(robot, point, base, arm, maps):
        record: dict[str, list[int]] = memo.setdefault(("grasp_record", obj.name, name), {})
        targets = pick_targets(world, robot, obj, name, base, memo)
        targets.sort(key=lambda t: _rank(record, t.grasp))
        tries = _restarts(robot, name, restarts)
        for target in targets:
            tally = record.setdefault(target.grasp, [0, 0])  # [worked, failed]
            reach = _pick_at(world, robot, name, base, target, seed, tries, touched, obj)
            if reach is not None:
                tally[0] += 1
                return reach
            tally[1] += 1
    return None


def _restarts(robot: RobotObject, arm: str, restarts: int) -> int:
    """IK restarts per grasp of ``arm``: at least :data:`PALM_IK_RESTARTS` for a palm hand.

    A palm hand takes a mug by its handle only, in five ways or fewer (a gripper has six
    to ten), each with the wrist in a narrow range: two restarts missed the TIAGo++'s
    handle grasp from the side that the pick's IK reached, and no stand was taken."""
    if robot.description.arms[arm].gripper is None or hand_of(robot.description, arm).palm is None:
        return restarts
    return max(restarts, PALM_IK_RESTARTS)


def _rank(record: dict[str, list[int]], grasp: str) -> tuple[int, int]:
    worked, failed = record.get(grasp, (0, 0))
    return (-worked, failed)


def _pick_at(
    world: World,
    robot: RobotObject,
    arm: str,
    base: Pose,
    target: PickTarget,
    seed: Mapping[str, float],
    restarts: int,
    touched: set[str] | None = None,
    obj: WorldObject | None = None,
) -> Reach | None:
    """The pick's motions for one grasp from ``base``: pre-grasp, grasp, collisions (the
    objects hit added to ``touched``); at the grasp the hand may touch only ``obj``, as
    shallowly as the pick lets it (any object, at any depth, without ``obj``)."""
    desc = robot.description
    pre = solve_at_stand(desc, arm, target.pre_grasp_in_base, seed, restarts)
    if not pre.success:
        return None
    grasp = _solve_near(desc, arm, target.grasp_in_base, pre, seed, restarts)
    if not grasp.success:
        return None
    at_grasp = _moved(base, grasp.base_motion)
    hit = _grasp_hits(world, robot, arm, at_grasp, grasp.joint_positions, obj)
    if not hit:
        hit = _pre_grasp_hits(world, robot, arm, _moved(base, pre.base_motion), pre.joint_positions)
    if hit:
        if touched is not None:
            touched.update(hit)
        return None
    return Reach(arm, dict(grasp.joint_positions), target.grasp_in_base, grasp.base_motion)


def _grasp_hits(
    world: World,
    robot: RobotObject,
    arm: str,
    stand: Pose,
    joints: Mapping[str, float],
    obj: WorldObject | None,
) -> list[str]:
    """What the robot touches at the grasp but its hand, and, the hand open as the pick
    has it there, whether the hand goes deeper into ``obj`` than the pick's bound (the
    TIAGo's thumb went 6.5 mm into the mug: every IK solution of the pick was refused)."""
    hit = touched_objects(world, robot, arm, stand, joints, allow_hand=True)
    gripper = robot.description.arms[arm].gripper
    if hit or obj is None:
        return hit
    opened = dict(joints)
    if gripper is not None and not gripper.is_suction:
        opened.update(gripper.at(1.0))
    return touched_objects(world, robot, arm, stand, opened, allow_hand=True, touching=obj.name)


def _pre_grasp_hits(
    world: World, robot: RobotObject, arm: str, stand: Pose, joints: Mapping[str, float]
) -> list[str]:
    """What the robot touches at the pre-grasp: with the gripper as it is, and where that
    touches something, with it open, as the pick has it there (it opens first). Kevin's
    closed fingers reach 11 cm past its tool frame, into a mug 10 cm ahead; open, they
    pass either side of it."""
    hit = touched_objects(world, robot, arm, stand, joints)
    gripper = robot.description.arms[arm].gripper
    if not hit or gripper is None or gripper.is_suction:
        return hit
    return touched_objects(world, robot, arm, stand, {**joints, **gripper.at(1.0)})


def _solve_near(
    desc: RobotDescription,
    arm: str,
    target: Pose,
    near: IKResult,
    seed: Mapping[str, float],
    restarts: int,
) -> IKResult:
    """IK for ``target`` (base frame) starting from the solution ``near``: first the arm alone
    from where ``near`` put the base (a grasp is a short way from its pre-grasp), then with
    the base."""
    start = {**seed, **near.joint_positions}
    motion = near.base_motion
    here = target if motion is None else motion.pose().inverse() * target
    options = IKOptions(use_torso=desc.torso_joint is not None, max_restarts=restarts)
    still = solve_ik(desc, arm, here, seed=start, options=options)
    if still.success:
        return replace(still, base_motion=motion)
    return solve_at_stand(desc, arm, target, start, restarts) if motion is not None else still


def _moved(base: Pose, motion: BaseMotion | None) -> Pose:
    return base if motion is None else base * motion.pose()


def reach_to_place(
    world: World,
    robot: RobotObject,
    target: Pose,
    base: Pose,
    arm: str | None = None,
    restarts: int = IK_RESTARTS,
    touched: set[str] | None = None,
) -> Reach | None:
    """The first way the place plan will try that works from ``base``, or None.

    ``target`` is where the held object's frame goes (map). One works if IK reaches the
    tool's pose there, then the hand's retreat towards the wrist, and at the put only the
    hand (and what it holds) touches anything. None when the robot holds nothing.
    ``touched`` gathers the objects the ways that reached collided with.
    """
    desc = robot.description
    seed = world.joint_states(robot)
    for way in place_targets(world, robot, target, base, arm):
        put = solve_at_stand(desc, way.arm, way.place_in_base, seed, restarts)
        if not put.success:
            continue
        back = _solve_near(desc, way.arm, way.retreat_in_base, put, seed, restarts)
        if not back.success:
            continue
        at = _moved(base, put.base_motion)
        hit = touched_objects(world, robot, way.arm, at, put.joint_positions, allow_hand=True)
        if not hit:
            return Reach(way.arm, dict(put.joint_positions), way.place_in_base, put.base_motion)
        if touched is not None:
            touched.update(hit)
    return None


def reachable(query: LocationQuery, pose: Pose) -> bool:
    """Whether the robot at ``pose`` can pick the object up (:func:`reach_to_pick`), put
    what it holds down at the ``target`` (:func:`reach_to_place`), or, hands empty, reach
    the ``target`` with the tool from above; IK with the torso free. A refused stand blames
    what the arm would have hit where IK reached."""
    robot, world = query_robot(query), query.world
    arm = query.designator.get("arm")
    wanted = query.designator.get("object")
    maps, budget = query.reach_maps, STAND_IK_RESTARTS
    touched: set[str] = set()
    with placed(world, robot, pose):  # standing there: the checks move only the arm
        if wanted is not None:
            obj = query.object(wanted, "object")
            memo = query.memo
            found = reach_to_pick(world, robot, obj, pose, arm, maps, budget, memo, touched)
        else:
            value = query.designator.get("target")
            point = query.point(value, "target")
            if held_objects(world, robot):
                spot = _spot(value, point)
                found = reach_to_place(world, robot, spot, pose, arm, budget, touched)
            else:
                found = reach_point(world, robot, point, pose, arm, maps, budget)
    if found is None:
        query.blame.blocking(touched)
    return found is not None


def _spot(value: object, point: Vector3) -> Pose:
    """Where the held object's frame goes: the target's pose, or the point unturned."""
    if isinstance(value, PoseStamped):
        return Pose(point, value.pose.orientation)
    return Pose(point, value.orientation) if isinstance(value, Pose) else Pose(point)

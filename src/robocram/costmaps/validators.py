"""Validators: a candidate pose is taken only if the world agrees it works.

Each is ``fn(query, pose) -> bool``. They place the robot (or the object) at the pose,
ask the world, and put everything back exactly as it was. A robot stands there as it
arrives, with its arms parked (CRAM parks them before driving).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from robocram.costmaps.camera_aim import aimed_cameras
from robocram.costmaps.cost_layer import LocationQuery
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grasps import GRASP_YAWS, approach_axis, grasp_point, grasp_poses, top_down
from robocram.costmaps.reachability_map import ReachabilityMaps
from robocram.costmaps.surface_costs import seen_through
from robocram.kinematics import (
    BaseMotion,
    IKOptions,
    IKResult,
    PlanarBase,
    base_in_ik,
    solve_ik,
)
from robocram.robots import ArmDescription, RobotDescription
from robocram.tf import Pose, Vector3
from robocram.world import Camera, RayHit, RobotObject, World, WorldObject
from robocram.world.link_contacts import link_contacts
from robocram.world.visibility import ray_visibility

Validator = Callable[[LocationQuery, Pose], bool]
VISIBLE_FRACTION = 0.9  # share of the object the aimed camera must see
VISIBILITY_RAYS = 12  # rays per side of the grid over the object's outline (world: 24)
SEEN_WITHIN = 0.02  # [m] a ray to a target point stopping this close to it sees it
STAND_TRAVEL = PlanarBase(0.25, 0.25, math.pi / 4)  # a base-in-IK arm's adjustment at a stand
IK_RESTARTS = 30  # random restarts per grasp: a miss costs a bounded, counted budget
STAND_IK_RESTARTS = 2  # per grasp when judging a candidate stand: a reachable grasp
# converges in the first descents (kitchen, PR2/HSR/Boxy), a miss at 30 costs ~7 ms a grasp;
# a stand rejected wrongly only costs the next candidate, a stand accepted is still sound


@contextmanager
def placed(world: World, obj: WorldObject, pose: Pose) -> Iterator[None]:
    """Put ``obj`` at ``pose`` for the block; restore its pose afterwards."""
    before = world.pose(obj)
    world.set_pose(obj, pose)
    try:
        yield
    finally:
        world.set_pose(obj, before)


@contextmanager
def parked(world: World, robot: RobotObject) -> Iterator[None]:
    """Arms (not the neck) at their parking joint values for the block, as when driving;
    an arm that holds something stays as it is (the plan carries it so: Boxy's bowl,
    carried above the table's height, hit the table at every stand a parked check passed)."""
    desc = robot.description
    holding = set(world.bodies.attachments(robot).values())
    parking = {
        joint: value
        for name, arm in desc.arms.items()
        if name != desc.neck_arm and not holding & _hand_of(arm)
        for joint, value in arm.parking.items()
    }
    before = world.joint_states(robot)
    if all(abs(before[j] - v) < 1e-9 for j, v in parking.items()):
        yield  # already parked (an enclosing block parked them): nothing to set or undo
        return
    world.set_joint_states(robot, parking)
    try:
        yield
    finally:
        world.set_joint_states(robot, {j: before[j] for j in parking})


def _hand_of(arm: ArmDescription) -> set[str]:
    """The links an arm holds things by."""
    return {arm.end_effector_link, arm.tool_frame, *arm.hand_links, *arm.gripper_links}


def query_robot(query: LocationQuery) -> RobotObject:
    if query.robot is None:
        raise CostmapInputError(f"{query.designator.description} names no robot", None)
    return query.robot


def robot_collision_free(query: LocationQuery, pose: Pose) -> bool:
    """Whether the robot standing at ``pose``, arms parked, touches nothing but the floor;
    nor does what it holds (driving there checks both, so a stand that only the robot
    clears would be refused by the drive). A refused stand blames what was touched."""
    robot, world = query_robot(query), query.world
    floors = world.objects(type="floor")
    with placed(world, robot, pose), parked(world, robot):
        touched = link_contacts(world, robot, ignore=floors)
        if not touched:
            touched = [
                pair
                for held in world.bodies.attachments(robot)
                for pair in link_contacts(world, world.object(held), ignore=floors)
            ]
    if touched:
        query.blame.blocking(other for _, other in touched)
    return not touched


def object_collision_free(query: LocationQuery, pose: Pose) -> bool:
    """Whether the ``for_`` object at ``pose`` touches nothing but its support (and the
    bodies ``see_through`` names: the robot asking moves out of the way before it puts it)."""
    obj = query.object(query.designator.get("for_"), "for_")
    supports = [(k, query.designator.get(k)) for k in ("on", "in_")]
    ignore = [query.part(value, key)[0] for key, value in supports if value is not None]
    ignore += [body for body in seen_through(query) if body is not obj]
    with placed(query.world, obj, pose):
        return not query.world.contacts.collisions(obj, ignore)


def visible(query: LocationQuery, pose: Pose) -> bool:
    """Whether the robot at ``pose``, arms parked, camera aimed at the target, sees 90 % of it.

    A refused stand blames what the rays met before the target."""
    robot, world = query_robot(query), query.world
    target = query.designator.get("object")
    with placed(world, robot, pose), parked(world, robot):
        if target is None:
            point = query.point(query.designator.get("target"), "target")
            hits = [point_blocker(world, c, point) for c in aimed_cameras(world, robot, point)]
            if all(hit is not None for hit in hits):
                query.blame.occluding([hit.obj.name for hit in hits[:1] if hit is not None])
                return False
            return True
        obj = query.object(target, "object")
        views = [
            ray_visibility(world, camera, obj, VISIBILITY_RAYS)
            for camera in aimed_cameras(world, robot, query.point(obj, "object"))
        ]
    if any(seen.fraction >= VISIBLE_FRACTION for seen in views):
        return True
    query.blame.occluding(views[0].occluders)
    return False


def sees_point(world: World, camera: Camera, point: Vector3) -> bool:
    """Whether nothing stands between ``camera`` and ``point`` (within 2 cm of it).

    The ray starts at the camera's near plane, as the world's visibility rays do: a camera
    inside its own housing (Boxy's Kinect link) sees nothing closer than that.
    """
    return point_blocker(world, camera, point) is None


def point_blocker(world: World, camera: Camera, point: Vector3) -> RayHit | None:
    """Where the ray from ``camera`` to ``point`` meets something short of it (farther than
    2 cm from it), or None when the camera sees the point (:func:`sees_point`)."""
    origin = np.asarray(camera.pose.position, float)
    ahead = np.asarray(point, float) - origin
    length = float(np.linalg.norm(ahead))
    if length <= camera.near:
        return None
    start = origin + ahead * (camera.near / length)
    hit = world.view.ray_cast(tuple(start.tolist()), point)
    return None if hit is None or math.dist(hit.position, point) < SEEN_WITHIN else hit


@dataclass(frozen=True)
class Reach:
    """How a robot standing at a base pose grasps an object."""

    arm: str
    joint_positions: dict[str, float]  # [rad | m] torso included
    tool_in_base: Pose  # the grasp, in the robot's root link
    base_motion: BaseMotion | None = None  # the base's own adjustment (arms < 6 joints)


def robot_arms(robot: RobotObject, arm: str | None) -> list[str]:
    """``[arm]`` if given and the robot has it, else all of the robot's arms but the neck."""
    desc = robot.description
    if arm is None:
        return [a for a in desc.arms if a != desc.neck_arm]
    if arm not in desc.arms:
        raise CostmapInputError(
            f"robot {robot.name!r} has no arm {arm!r}; it has {sorted(desc.arms)}", arm
        )
    return [arm]


def reach_object(
    world: World,
    robot: RobotObject,
    obj: WorldObject,
    base: Pose,
    arm: str | None = None,
    maps: ReachabilityMaps | None = None,
    restarts: int = IK_RESTARTS,
) -> Reach | None:
    """An IK solution (torso free) grasping ``obj`` from above from ``base``, or None.

    An arm that reaches with the base (``kinematics.base_in_ik``, the HSR's) may adjust
    the base by up to :data:`STAND_TRAVEL` from ``base``, as it will when it grasps.

    With reachability ``maps``, arms are tried best first and those the map says cannot
    get there are skipped: IK on a hopeless target only burns its whole budget.
    """
    return _reach(
        world,
        robot,
        grasp_point(world, obj),
        lambda name: grasp_poses(world, obj, robot.description, name, base),
        base,
        arm,
        maps,
        restarts,
    )


def reach_point(
    world: World,
    robot: RobotObject,
    point: Vector3,
    base: Pose,
    arm: str | None = None,
    maps: ReachabilityMaps | None = None,
    restarts: int = IK_RESTARTS,
) -> Reach | None:
    """An IK solution (torso free) putting the tool over map ``point`` from above, or None.

    For a location reaching a place rather than an object (CRAM's ``(reachable-for ?robot)
    (location ?target)``): the spot an object is to be put down at, a point to touch.
    """
    desc = robot.description
    in_base = base.inverse().transform_point(point)
    return _reach(
        world,
        robot,
        point,
        lambda name: [Pose(in_base, top_down(approach_axis(desc, name), y)) for y in GRASP_YAWS],
        base,
        arm,
        maps,
        restarts,
    )


def _reach(
    world: World,
    robot: RobotObject,
    point: Vector3,
    targets: Callable[[str], list[Pose]],
    base: Pose,
    arm: str | None,
    maps: ReachabilityMaps | None,
    restarts: int,
) -> Reach | None:
    """The first IK solution for an arm's tool ``targets`` (base frame) around map ``point``."""
    desc = robot.description
    seed = world.joint_states(robot)
    for name in hopeful_arms(robot, point, base, arm, maps):
        for target in targets(name):
            result = solve_at_stand(desc, name, target, seed, restarts)
            if result.success:
                return Reach(name, dict(result.joint_positions), target, result.base_motion)
    return None


def hopeful_arms(
    robot: RobotObject, point: Vector3, base: Pose, arm: str | None, maps: ReachabilityMaps | None
) -> list[str]:
    """The arms to try for map ``point``: best first by the maps, hopeless ones dropped."""
    arms = robot_arms(robot, arm)
    if maps is None:
        return arms
    in_base = base.inverse().transform_point(point)
    scores = {a: maps.get(robot.description, a).score_at(in_base) for a in arms}
    return sorted((a for a in arms if scores[a] > 0), key=lambda a: -scores[a])


def solve_at_stand(
    desc: RobotDescription, arm: str, target: Pose, seed: Mapping[str, float], restarts: int
) -> IKResult:
    """IK for ``arm``'s tool at ``target`` (base frame), torso free; an arm that reaches with
    the base may move it within :data:`STAND_TRAVEL`."""
    return solve_ik(
        desc,
        arm,
        target,
        seed=seed,
        options=IKOptions(
            use_torso=desc.torso_joint is not None,
            max_restarts=restarts,
            base=STAND_TRAVEL if base_in_ik(desc, arm) else None,
        ),
    )

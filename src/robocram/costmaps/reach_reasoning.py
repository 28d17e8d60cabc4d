"""CRAM's reach reasoning: ``reachable/2``, ``pose_reachable/2`` and ``blocking/4``.

In Python and as predicates of the world's knowledge base. Robots stay where they stand
(an arm that reaches with the base adjusts it a little, ``validators.STAND_TRAVEL``);
IK decides (torso free, grasps from above), and ``blocking`` puts the arm at the grasp to
see what it would hit, then restores the joints. ``pose_reachable/3`` asks of one arm;
``lift_clearance/4`` says how far an object must rise to clear a link (a bowl out of its
drawer), so a pick can ask, before it grips, whether that lift is in reach;
``line_stand/5`` where an arm reaching along a telescope takes its hand in and out along
the approach line by the telescope alone (``line_stand.py``).
"""

from __future__ import annotations

from collections.abc import Iterator

from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.line_stand import line_stand
from robocram.costmaps.validators import (
    IK_RESTARTS,
    STAND_TRAVEL,
    placed,
    reach_object,
    robot_arms,
)
from robocram.kinematics import IKOptions, base_in_ik, solve_ik
from robocram.knowledge import Source, register_predicates
from robocram.logic import KnowledgeBase, Value, Var
from robocram.tf import Pose, PoseStamped
from robocram.world import RobotObject, World, WorldObject

Solutions = Iterator[tuple[Value, ...] | None]
LIFT_MARGIN = 0.02  # [m] an object lifted out of a link clears its top by this


def _pose_in_map(pose: Value) -> Pose:
    if isinstance(pose, PoseStamped):
        if pose.frame_id != "map":
            raise CostmapInputError(
                f"pose_reachable needs a pose in 'map', got frame {pose.frame_id!r}; "
                "transform it first",
                pose.frame_id,
            )
        return pose.pose
    return Pose.coerce(pose)


def pose_reachable(
    world: World, robot: str | RobotObject, pose: Pose | PoseStamped, arm: str | None = None
) -> bool:
    """Whether an arm of ``robot``, standing where it is, brings its tool to ``pose`` (map)."""
    body = world.robot(robot)
    desc = body.description
    target = world.pose(body).inverse() * _pose_in_map(pose)
    seed = world.joint_states(body)
    use_torso = desc.torso_joint is not None
    return any(
        solve_ik(
            desc,
            name,
            target,
            seed=seed,
            options=IKOptions(
                use_torso=use_torso,
                max_restarts=IK_RESTARTS,
                base=STAND_TRAVEL if base_in_ik(desc, name) else None,
            ),
        )
        for name in robot_arms(body, arm)
    )


def lift_clearance(world: World, obj: str | WorldObject, body: str, link: str) -> float:
    """How far [m] ``obj`` must rise, as it is now, for its bottom to clear the top of
    ``link`` of ``body`` by :data:`LIFT_MARGIN` (0 when it already does): PyBullet's
    bounds of both.

    Raises:
        CostmapInputError: ``body`` has no link ``link`` with bounds.
    """
    boxes = world.contacts.link_aabbs(body)
    if link not in boxes:
        raise CostmapInputError(
            f"{body!r} has no link {link!r} to lift out of; it has {sorted(boxes)}", link
        )
    low = min(lo[2] for lo, _ in world.contacts.link_aabbs(obj).values())
    return max(0.0, boxes[link][1][2] + LIFT_MARGIN - low)


def reachable(
    world: World, robot: str | RobotObject, obj: str | WorldObject, arm: str | None = None
) -> bool:
    """Whether ``robot``, standing where it is, reaches a grasp of ``obj`` from above."""
    body = world.robot(robot)
    return reach_object(world, body, world.object(obj), world.pose(body), arm) is not None


def blocking(
    world: World, robot: str | RobotObject, arm: str, obj: str | WorldObject
) -> list[str] | None:
    """Objects ``arm`` would hit grasping ``obj`` (sorted names), None if it cannot reach it."""
    body, target = world.robot(robot), world.object(obj)
    reach = reach_object(world, body, target, world.pose(body), arm)
    if reach is None:
        return None
    model = body.description.model
    before = {  # followers come back with their masters
        j: v for j, v in world.joint_states(body).items() if model.joints[j].mimic is None
    }
    stand = world.pose(body)
    moved = stand * reach.base_motion.pose() if reach.base_motion is not None else stand
    try:
        with placed(world, body, moved):  # as the arm would adjust its base to grasp
            world.set_joint_states(body, reach.joint_positions)
            skip = [target, *world.objects(type="floor")]
            return sorted(o.name for o in world.contacts.collisions(body, skip))
    finally:
        world.set_joint_states(body, before)


def _names(world: World, arg: object, robots: bool) -> list[str]:
    if isinstance(arg, Var):
        pool = world.robots() if robots else [o for o in world.objects() if o.type != "floor"]
        return [o.name for o in pool if robots or not isinstance(o, RobotObject)]
    return [arg] if isinstance(arg, str) and arg in world else []


def install_reach_predicates(kb: KnowledgeBase, world: World) -> None:
    """Add ``reachable/2``, ``pose_reachable/2`` and ``blocking/4`` about ``world`` to ``kb``."""

    @kb.predicate("reachable", 2)
    def reachable_(rob: object, obj: object) -> Solutions:
        for r in _names(world, rob, robots=True):
            yield from ((r, o) for o in _names(world, obj, robots=False) if reachable(world, r, o))

    @kb.predicate("pose_reachable", 2)
    def pose_reachable_(rob: object, pose: Value) -> Solutions:
        if not isinstance(pose, Var):
            yield from (
                (r, pose) for r in _names(world, rob, True) if pose_reachable(world, r, pose)
            )

    def pose_reachable_arm(rob: object, arm: Value, pose: Value) -> Solutions:
        if isinstance(pose, Var):
            return
        for r in _names(world, rob, True):
            arms = robot_arms(world.robot(r), None)
            asked = arms if isinstance(arm, Var) else [a for a in arms if a == arm]
            yield from ((r, a, pose) for a in asked if pose_reachable(world, r, pose, a))

    def lift_clearance_(obj: object, body: object, link: object, rise: Value) -> Solutions:
        names = _names(world, obj, robots=False)
        if not (isinstance(body, str) and body in world and isinstance(link, str)):
            return
        if link in world.contacts.link_aabbs(body):
            yield from ((o, body, link, lift_clearance(world, o, body, link)) for o in names)

    def line_stand_(rob: object, arm: object, out: Value, grasp: Value, stand: Value) -> Solutions:
        if not (isinstance(arm, str) and isinstance(out, PoseStamped)):
            return
        if not isinstance(grasp, PoseStamped):
            return
        for r in _names(world, rob, True):
            if arm in robot_arms(world.robot(r), None):
                found = line_stand(world, r, arm, _pose_in_map(out), _pose_in_map(grasp))
                if found is not None:
                    yield (r, arm, out, grasp, PoseStamped.from_pose("map", found))

    register_predicates(
        kb,
        Source.REASONING,
        {
            "pose_reachable/3": pose_reachable_arm,
            "lift_clearance/4": lift_clearance_,
            "line_stand/5": line_stand_,
        },
    )

    @kb.predicate("blocking", 4)
    def blocking_(rob: object, arm: Value, obj: object, blockers: object) -> Solutions:
        for r in _names(world, rob, robots=True):
            arms = robot_arms(world.robot(r), None) if isinstance(arm, Var) else [arm]
            for a in arms:
                for o in _names(world, obj, robots=False):
                    found = blocking(world, r, a, o)
                    if found is not None:
                        yield (r, a, o, found)

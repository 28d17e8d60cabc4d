"""Why a zoo robot picks a kitchen item from no stand: its reach, or what its arm meets.

Run: ``.venv/bin/python benchmarks/pick_stand_probe.py NAME [--item mug-1] [--open 0.4]
[--back 0.8 0.7] [--across 0] [--turn 0] [--out-yaw -90] [--lift 0.89] [--seeds 15]
[--legs THIGH] [--trunk JOINT=RAD ...] [--crouch 0 0.1 ...] [--scene tabletop]``.

The robot (a name of ``robot_zoo.CORPUS``, drafted as there) stands in the kitchen with its
arms parked, its base's middle ``back`` [m] out of the counters' front from the item
(``out-yaw``: the map yaw out of them, -90 degrees for the north counters), ``across``
[m] along it, turned by ``turn`` [degrees] from facing it (90: its left flank). With
``--open`` the item's drawer (``drawer_unit_drawer_3`` for the bowl) is opened that far
and the item moved with it, as the search leaves it. Each stand prints the robot links
touching anything there (parked), then each grasp the pick would try (the validator's
``pick_targets``): for the pre-grasp, the grasp and a lift to ``lift`` [m] (map z; 0: no
lift), how far the best of ``seeds`` IK queries misses without a collision check (mm),
and, where it reaches, how deep the least deep solution goes into the kitchen and with
which links. ``--legs`` puts every ``*_thigh_joint`` there [rad] (a stance tried by hand,
the robot put back on the floor); ``--trunk`` sets joints by hand the same way (a
humanoid's trunk leaned: Rollin' Justin's ``torso2_joint=0.3``), ``--crouch`` probes every
stand again with the legged robot crouched each depth [m] (``kinematics.crouch``: the base
lowered, the soles kept; Centauro at the bowl's drawer, zoo37), and ``--scene tabletop``
puts it in the tabletop scene instead, the table standing for the counters (out-yaw 180:
the table lies along the map's x). Why it is kept: it says whether a stand nearer the item
would help (reach) or not (the arm meets the kitchen), as for the B1-Z1 and the
Ridgeback-UR5 (issue 37, session 32).
"""

from __future__ import annotations

import argparse
import math
import warnings
from collections.abc import Mapping
from pathlib import Path

from robot_zoo import parked_in_kitchen

from robocram.costmaps.pick_reach import PickTarget, pick_targets
from robocram.kinematics import solve_ik
from robocram.kinematics.crouch import crouched
from robocram.kinematics.ik_options import IKOptions
from robocram.robots.draft.stance import legs
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World
from robocram.world.link_contacts import link_contacts

DRAWERS = {"bowl-1": "drawer_unit_drawer_3"}  # the kitchen's drawer each item lies in
OUT = Path("/tmp/pick_stand_probe_drafts")
RESTARTS = 5  # descents after the first, per seeded query


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("name")
    parser.add_argument("--item", default="mug-1")
    parser.add_argument("--arm", default=None, help="default: every arm")
    parser.add_argument("--open", type=float, default=0.0, help="[m] the item's drawer")
    parser.add_argument("--back", type=float, nargs="+", default=[0.8, 0.7])
    parser.add_argument("--across", type=float, nargs="+", default=[0.0])
    parser.add_argument("--turn", type=float, nargs="+", default=[0.0])
    parser.add_argument("--out-yaw", type=float, default=-90.0)
    parser.add_argument("--lift", type=float, default=0.0)
    parser.add_argument("--seeds", type=int, default=15)
    parser.add_argument("--restarts", type=int, default=RESTARTS, help="per seeded query")
    parser.add_argument("--legs", type=float, default=None)
    parser.add_argument("--trunk", nargs="*", default=[], help="JOINT=RAD set by hand")
    parser.add_argument("--crouch", type=float, nargs="+", default=[0.0], help="[m] depths")
    parser.add_argument("--scene", choices=("kitchen", "tabletop"), default="kitchen")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    world, robot = _scene(args.name, args.scene)
    try:
        if args.legs is not None:
            legs = [j for j in world.joint_states(robot) if j.endswith("_thigh_joint")]
            world.set_joint_states(robot, dict.fromkeys(legs, args.legs))
        if args.trunk:
            by_hand = dict(_joint_value(word) for word in args.trunk)
            world.set_joint_states(robot, by_hand)
            set_now = world.joint_states(robot)
            print("trunk: " + ", ".join(f"{j} {set_now[j]:.3f}" for j in by_hand))
        if args.open:
            _open(world, args.item, args.open)
        z = _on_the_floor(world, robot)
        item = world.pose(args.item).position
        out = math.radians(args.out_yaw)
        standing = world.joint_states(robot)
        for depth in args.crouch:
            if depth:
                world.set_joint_states(robot, _crouch(world, robot, standing, depth))
            for back in args.back:
                for across in args.across:
                    for turn in args.turn:
                        x = item[0] + back * math.cos(out) - across * math.sin(out)
                        y = item[1] + back * math.sin(out) + across * math.cos(out)
                        yaw = out + math.pi + math.radians(turn)
                        stand = Pose((x, y, z - depth), quat.from_euler(0.0, 0.0, yaw))
                        print(
                            f"crouch {depth:.2f} back {back:.2f} across {across:+.2f} "
                            f"turn {turn:+.0f}:",
                            flush=True,
                        )
                        _probe(world, robot, stand, args)
            world.set_joint_states(robot, standing)
    finally:
        world.close()


def _scene(name: str, scene: str) -> tuple[World, str]:
    """The world and robot of the kitchen (arms parked) or of the tabletop scene."""
    if scene == "kitchen":
        kitchen = parked_in_kitchen(name, OUT)
        return kitchen.world, kitchen.robot
    from robot_zoo import CORPUS, _draft

    from robocram.scenes import tabletop_scene

    entry = next(r for r in CORPUS if r.name == name)
    table = tabletop_scene(_draft(entry, OUT))
    return table.world, table.robot


def _crouch(
    world: World, robot: str, standing: Mapping[str, float], depth: float
) -> dict[str, float]:
    """The leg joints that lower the base ``depth`` [m] with the soles kept."""
    desc = world.robot(robot).description
    feet = [leg.foot for leg in legs(desc.model, [x.end_effector_link for x in desc.arms.values()])]
    return crouched(desc.model, feet, standing, depth)


def _joint_value(word: str) -> tuple[str, float]:
    """``JOINT=RAD`` as a pair."""
    joint, _, value = word.partition("=")
    return joint, float(value)


def _obstacle(world: World) -> str:
    """What the arm must keep out of: the kitchen, else the table."""
    return "kitchen" if any(o.name == "kitchen" for o in world.objects()) else "table"


def _open(world: World, item: str, opening: float) -> None:
    """Open ``item``'s drawer by ``opening`` [m] and move the item along with it."""
    drawer = DRAWERS[item]
    before = world.link_pose("kitchen", drawer)
    world.set_joint_states("kitchen", {f"{drawer}_joint": opening})
    moved = world.link_pose("kitchen", drawer) * before.inverse()
    world.set_pose(item, moved * world.pose(item))


def _on_the_floor(world: World, robot: str) -> float:
    """The base's height [m] that puts the robot's lowest part on the floor, as it is now."""
    pose = world.pose(robot)
    return pose.position[2] - world.aabb(robot)[0][2]


def _probe(world: World, robot: str, stand: Pose, args: argparse.Namespace) -> None:
    world.set_pose(robot, stand)
    floors = world.objects(type="floor")
    touched = sorted(
        {
            f"{link}/{other}"
            for link, other in link_contacts(world, world.robot(robot), ignore=floors)
        }
    )
    print(f"  parked, touches: {', '.join(touched) or 'nothing'}")
    desc = world.robot(robot).description
    arms = [args.arm] if args.arm else list(desc.arms)
    seen: set[tuple[str, str, tuple[float, ...]]] = set()  # arm, grasp, where
    for arm in arms:
        for target in pick_targets(world, world.robot(robot), world.object(args.item), arm, stand):
            key = (arm, target.grasp, tuple(round(v, 3) for v in target.grasp_in_base.position))
            if key in seen:
                continue
            seen.add(key)
            print(f"  {arm} {target.grasp} {_targets_line(world, robot, arm, stand, target, args)}")


def _targets_line(
    world: World, robot: str, arm: str, stand: Pose, target: PickTarget, args: argparse.Namespace
) -> str:
    """The pre-grasp's, the grasp's and the lift's misses and depths on one line."""
    grasp = target.grasp_in_base
    poses = [("pre-grasp", target.pre_grasp_in_base), ("grasp", grasp)]
    if args.lift:
        up = (grasp.position[0], grasp.position[1], args.lift - stand.position[2])
        poses.append(("lift", Pose(up, grasp.orientation)))
    at = stand * grasp
    words = [f"at ({at.position[0]:+.3f}, {at.position[1]:+.3f}, {at.position[2]:.3f})"]
    for name, pose in poses:
        words.append(f"{name} {_best(world, robot, arm, pose, args.seeds, args.restarts)}")
    return "; ".join(words)


def _best(world: World, robot: str, arm: str, pose: Pose, seeds: int, restarts: int) -> str:
    """The least deep of ``seeds`` IK solutions for ``pose`` (base frame), or the miss
    (how far it lies beyond the arm's reach bound, if it does)."""
    desc = world.robot(robot).description
    seed = world.joint_states(robot)
    miss, best = math.inf, (math.inf, "")
    for k in range(seeds):
        result = solve_ik(
            desc, arm, pose, seed=seed, options=IKOptions(max_restarts=restarts, random_seed=k)
        )
        if not result.success:  # beyond the reach bound: no descent ran, the seed's error
            miss = min(miss, result.beyond_reach or result.position_error)
            continue
        best = min(best, _depth(world, robot, arm, result.joint_positions))
    if math.isinf(best[0]):
        return f"misses {miss * 1000:.0f} mm"
    return "clear" if best[0] <= 0.0 else f"{best[0] * 1000:.0f} mm into {best[1]}"


def _depth(world: World, robot: str, arm: str, joints: Mapping[str, float]) -> tuple[float, str]:
    """How deep [m] the robot at ``joints`` goes into the kitchen or table (the item aside),
    and between which links, or, 1 mm for any, which of its own links the arm then
    touches (its base link aside); the joints put back."""
    before = world.joint_states(robot)
    world.set_joint_states(robot, dict(joints))
    try:
        points = world.contacts.contact_points(robot, _obstacle(world))
        own = world.contacts.self_contacts(robot, _arm_pairs(world, robot, arm))
    finally:
        world.set_joint_states(robot, before)
    if points:
        worst = min(points, key=lambda p: p.distance)
        return -worst.distance, f"{worst.link_b} ({worst.link_a})"
    if own:
        return 0.001, "itself (" + ", ".join(sorted({f"{a}-{b}" for a, b in own})[:3]) + ")"
    return 0.0, ""


def _arm_pairs(world: World, robot: str, arm: str) -> list[tuple[str, str]]:
    """The arm's links (below its first joint) paired with every other link but its base's."""
    desc = world.robot(robot).description
    model = desc.model
    spec = desc.arms[arm]
    children: dict[str, list[str]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint.child)
    moved, todo = set(), [model.joints[spec.joints[0]].child]
    while todo:
        link = todo.pop()
        moved.add(link)
        todo.extend(children.get(link, []))
    links = {j.child for j in model.joints.values()} | {j.parent for j in model.joints.values()}
    others = sorted(links - moved - {spec.base_link})
    return [(a, b) for a in sorted(moved) for b in others]


if __name__ == "__main__":
    main()

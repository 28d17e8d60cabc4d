"""Why a zoo robot picks a kitchen item from no stand: its reach, or what its arm meets.

Run: ``.venv/bin/python benchmarks/pick_stand_probe.py NAME [--item mug-1] [--open 0.4]
[--back 0.8 0.7] [--across 0] [--turn 0] [--out-yaw -90] [--lift 0.89] [--seeds 15]
[--legs THIGH]``.

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
the robot put back on the floor). Why it is kept: it says whether a stand nearer the item
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
from robocram.kinematics.ik_options import IKOptions
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
    parser.add_argument("--legs", type=float, default=None)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    scene = parked_in_kitchen(args.name, OUT)
    world = scene.world
    try:
        if args.legs is not None:
            legs = [j for j in world.joint_states(scene.robot) if j.endswith("_thigh_joint")]
            world.set_joint_states(scene.robot, dict.fromkeys(legs, args.legs))
        if args.open:
            _open(world, args.item, args.open)
        z = _on_the_floor(world, scene.robot)
        item = world.pose(args.item).position
        out = math.radians(args.out_yaw)
        for back in args.back:
            for across in args.across:
                for turn in args.turn:
                    x = item[0] + back * math.cos(out) - across * math.sin(out)
                    y = item[1] + back * math.sin(out) + across * math.cos(out)
                    yaw = out + math.pi + math.radians(turn)
                    stand = Pose((x, y, z), quat.from_euler(0.0, 0.0, yaw))
                    print(f"back {back:.2f} across {across:+.2f} turn {turn:+.0f}:", flush=True)
                    _probe(world, scene.robot, stand, args)
    finally:
        world.close()


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
    seen: set[tuple[str, tuple[float, ...]]] = set()
    for arm in arms:
        for target in pick_targets(world, world.robot(robot), world.object(args.item), arm, stand):
            key = (target.grasp, tuple(round(v, 3) for v in target.grasp_in_base.position))
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
        words.append(f"{name} {_best(world, robot, arm, pose, args.item, args.seeds)}")
    return "; ".join(words)


def _best(world: World, robot: str, arm: str, pose: Pose, item: str, seeds: int) -> str:
    """The least deep of ``seeds`` IK solutions for ``pose`` (base frame), or the miss."""
    desc = world.robot(robot).description
    seed = world.joint_states(robot)
    miss, best = math.inf, (math.inf, "")
    for k in range(seeds):
        result = solve_ik(
            desc, arm, pose, seed=seed, options=IKOptions(max_restarts=RESTARTS, random_seed=k)
        )
        if not result.success:
            miss = min(miss, result.position_error)
            continue
        best = min(best, _depth(world, robot, result.joint_positions, item))
    if math.isinf(best[0]):
        return f"misses {miss * 1000:.0f} mm"
    return "clear" if best[0] <= 0.0 else f"{best[0] * 1000:.0f} mm into {best[1]}"


def _depth(world: World, robot: str, joints: Mapping[str, float], item: str) -> tuple[float, str]:
    """How deep [m] the robot at ``joints`` goes into the kitchen (the item aside), and
    between which links; the joints put back."""
    before = world.joint_states(robot)
    world.set_joint_states(robot, dict(joints))
    try:
        points = world.contacts.contact_points(robot, "kitchen")
    finally:
        world.set_joint_states(robot, before)
    if not points:
        return 0.0, ""
    worst = min(points, key=lambda p: p.distance)
    return -worst.distance, f"{worst.link_b} ({worst.link_a})"


if __name__ == "__main__":
    main()

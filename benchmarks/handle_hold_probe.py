"""Where a zoo robot's hold of the kitchen bowl drawer's handle fails: reach or collision.

Run: ``.venv/bin/python benchmarks/handle_hold_probe.py NAME [--arm right] [--back 0.6 0.45]
[--pitch 0 45 90] [--along -0.035 0 0.035] [--out 0] [--travel 0.15] [--restarts 30]
[--opening bar | FRACTION] [--lower 0.05 0.1 ...] [--front 40]``.

The robot (a name of ``robot_zoo.CORPUS``, drafted as there) stands facing the drawer,
``back`` [m] from its handle, the arm's shoulder in line with it, its arms parked, the
fingers open. Each hold frame (``along`` [m] along the bar from its middle, turned down by
``pitch`` [degrees] as ``motion.part_path.from_above`` does, the tool ``out`` [m] back
along the approach: a shallower hold) is asked of IK with each grasp
roll as opening the drawer asks it: the hand may touch the handle only, the base free
within ``travel`` [m] (rad: 3x). A line says whether IK held it, how far its best missed (mm, rad),
how many solutions met something and the first pair. Then IK without the collision check:
how deep the robot's links then go into the kitchen other than the handle, so a hold
refused only by a collision shows as such. ``--opening`` opens the fingers only part of
the way (``bar``: as wide as the bar needs, ``projection.bar_opening``), to see whether a
narrower hand clears what a fully open one meets. ``--lower`` [m] lowers the robot's whole body
by each value in turn, a stand-in for bent knees (a legged robot's lowered shoulders): only
the base's z goes down, the feet sink into the floor (which no check counts); after each a
line says whether any hold from the front (up to ``--front`` degrees down) was both reached
and clear, and by how much the nearest missed. With ``--bend`` the legs bend instead, by
``kinematics.crouch`` (the feet kept where they stand, the knees forward). Why it is kept:
TALOS's miss of 2-4 mm looked like reach (session 30, issue 37); this shows which holds a
nearer base reaches and what they meet, and (``--lower``) how far down a hold comes free.
"""

from __future__ import annotations

import argparse
import math
import warnings
from pathlib import Path

import numpy as np
from robot_zoo import parked_in_kitchen

from robocram.costmaps.grasps import shoulder_offset
from robocram.grasping import palm_hold
from robocram.kinematics import IKResult, PlanarBase, solve_ik
from robocram.kinematics.crouch import crouched
from robocram.kinematics.ik_options import IKOptions
from robocram.motion.part_path import ROLLS, from_above, pull_frame
from robocram.projection import ProjectedRobot
from robocram.projection.arm import collision_check
from robocram.projection.articulation import HANDLE_HALF_WIDTH, _holding, approach_axis
from robocram.projection.bar_opening import bar_opening, gap_at
from robocram.projection.gripper import open_gripper
from robocram.projection.navigation import moved_base
from robocram.projection.suction import on_the_face
from robocram.robots.draft.stance import legs
from robocram.tf import Pose
from robocram.tf import quaternion as quat

DRAWER = "drawer_unit_drawer_3"  # the bowl's drawer, its handle 0.75 m up
OUT = Path("/tmp/handle_hold_probe_drafts")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("name")
    parser.add_argument("--arm", default="right")
    parser.add_argument("--back", type=float, nargs="+", default=[0.6, 0.45])
    parser.add_argument("--pitch", type=float, nargs="+", default=[0.0, 45.0, 90.0])
    parser.add_argument("--along", type=float, nargs="+", default=[-0.035, 0.0, 0.035])
    parser.add_argument("--out", type=float, nargs="+", default=[0.0])
    parser.add_argument("--travel", type=float, default=0.15)
    parser.add_argument("--restarts", type=int, default=30)
    parser.add_argument("--opening", default="1", help="fraction open, or 'bar'")
    parser.add_argument("--lower", type=float, nargs="+", default=[0.0], help="[m] base z down")
    parser.add_argument("--front", type=float, default=40.0, help="[deg] down: from the front")
    parser.add_argument("--bend", action="store_true", help="lower by bending the legs")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    scene = parked_in_kitchen(args.name, OUT)
    world = scene.world
    try:
        desc = world.robot(scene.robot).description
        handle = f"{DRAWER}_handle"
        at = world.link_pose("kitchen", handle)
        out = quat.rotate(at.orientation, (1.0, 0.0, 0.0))  # the kitchen's handle x: its front
        facing = quat.from_euler(0.0, 0.0, math.atan2(-out[1], -out[0]))
        z = world.pose(scene.robot).position[2]
        side = shoulder_offset(desc, args.arm)  # [m] across the base, left positive
        travel = PlanarBase(args.travel, args.travel, 3 * args.travel)
        standing = world.joint_states(scene.robot)
        feet = [
            leg.foot for leg in legs(desc.model, [a.end_effector_link for a in desc.arms.values()])
        ]
        for lower in args.lower:
            rows: list[tuple[float, bool, float, str]] = []
            for back in args.back:
                across = quat.rotate(facing, (0.0, side, 0.0))
                x = at.position[0] + out[0] * back - across[0]
                y = at.position[1] + out[1] * back - across[1]
                world.set_pose(scene.robot, Pose((x, y, z - lower), facing))
                if args.bend:
                    world.set_joint_states(scene.robot, crouched(desc.model, feet, standing, lower))
                robot = ProjectedRobot.of(world, scene.robot)
                open_gripper(robot, args.arm)  # as the hand comes to the handle: open
                _part_way(robot, args.arm, args.opening)
                rows += _probe(robot, args, back, travel)
            if lower or len(args.lower) > 1:
                _lowered(lower, [r for r in rows if r[0] <= args.front], args.front)
    finally:
        world.close()


def _part_way(robot: ProjectedRobot, arm: str, opening: str) -> None:
    """Put the fingers ``opening`` of the way open (``bar``: as wide as the bar needs)."""
    handle = f"{DRAWER}_handle"
    fraction = bar_opening(robot, arm, "kitchen", handle) if opening == "bar" else float(opening)
    gripper = robot.arm(arm).gripper
    if fraction is None or gripper is None:
        return
    robot.world.set_joint_states(robot.name, gripper.at(fraction))
    width = gap_at(robot, arm, fraction) * 1000
    print(f"opening {fraction:.3f} of full: {width:.1f} mm between the fingers", flush=True)


def _probe(
    robot: ProjectedRobot, args: argparse.Namespace, back: float, travel: PlanarBase
) -> list[tuple[float, bool, float, str]]:
    """Print a line per hold; return (pitch [deg], held, miss [mm], unchecked) of each."""
    rows: list[tuple[float, bool, float, str]] = []
    world, arm, handle = robot.world, args.arm, f"{DRAWER}_handle"
    palm = palm_hold(robot.description, arm, HANDLE_HALF_WIDTH)  # as move_part holds it
    axis = approach_axis(robot, arm) if palm is None else np.asarray(palm[0])
    pull = pull_frame(world, "kitchen", f"{DRAWER}_joint", handle)
    check = collision_check(robot, arm, "allow_hand", f"kitchen/{handle}")
    seed = world.joint_states(robot.name)
    gripper = robot.arm(arm).gripper
    suction = gripper is not None and gripper.is_suction
    for degrees in args.pitch:
        frame = from_above(pull, math.radians(degrees)) if degrees else pull
        if suction:  # its frame on the face it touches, as handle_holds puts it
            frame = on_the_face(robot, "kitchen", handle, frame)
        for along, out in ((a, o) for a in args.along for o in args.out):
            for roll in ROLLS:
                on_bar = world.link_pose("kitchen", handle) * Pose((0.0, along, 0.0))
                target = on_bar * frame * Pose((out, 0.0, 0.0))
                in_base = robot.base_pose().inverse() * target * _holding(axis, roll, palm)
                options = IKOptions(base=travel, max_restarts=args.restarts)
                held = solve_ik(robot.description, arm, in_base, seed=seed, options=options,
                                collision_check=check)  # fmt: skip
                free = solve_ik(robot.description, arm, in_base, seed=seed, options=options)
                pair = held.colliding_pairs[0] if held.colliding_pairs else ("", "")
                deepest = _deepest(robot, free)
                rows.append((degrees, held.success, held.position_error * 1000, deepest))
                print(
                    f"back {back:.2f} pitch {degrees:4.0f} along {along:+.3f} out {out:.3f} "
                    f"roll {roll:+.2f}: "
                    f"held {int(held.success)} miss {held.position_error * 1000:5.1f} mm "
                    f"{held.orientation_error:.2f} rad "
                    f"met {held.rejected_in_collision:3d} {pair[0]}/{pair[1]}; "
                    f"unchecked: {deepest}",
                    flush=True,
                )
    return rows


def _lowered(lower: float, rows: list[tuple[float, bool, float, str]], front: float) -> None:
    """One line: whether the body lowered by ``lower`` [m] held the handle from the front."""
    held = [r for r in rows if r[1]]
    reached = [r for r in rows if not r[3].startswith("no")]
    clear = [r for r in rows if r[3].startswith("clear")]
    least = min((r[2] for r in rows), default=math.nan)
    print(
        f"LOWER {lower:.2f} m, 0-{front:.0f} degrees down: held {len(held)} of {len(rows)}; "
        f"reached unchecked {len(reached)}, of them clear {len(clear)}; "
        f"least miss (checked) {least:.1f} mm; "
        f"{'; '.join(sorted({r[3] for r in rows if not r[3].startswith('no')})[:3])}",
        flush=True,
    )


def _deepest(robot: ProjectedRobot, result: IKResult) -> str:
    """How deep [mm] the robot, put where ``result`` says, goes into the kitchen other than
    the handle, and between which links; then put back."""
    if not result.success:
        miss = result.position_error * 1000
        return f"no solution ({miss:.1f} mm, {result.orientation_error:.2f} rad)"
    world = robot.world
    base, joints = robot.base_pose(), world.joint_states(robot.name)
    try:
        if result.base_motion is not None:
            world.set_pose(robot.name, moved_base(robot, result.base_motion))
        world.set_joint_states(robot.name, dict(result.joint_positions))
        every = world.contacts.contact_points(robot.name, "kitchen")
        points = [p for p in every if p.link_b != f"{DRAWER}_handle"]
        bar = min((p for p in every if p not in points), key=lambda p: p.distance, default=None)
        moved = math.dist(base.position, world.pose(robot.name).position)
    finally:
        world.set_pose(robot.name, base)
        world.set_joint_states(robot.name, joints)
    in_bar = "" if bar is None else f" (the bar: {-bar.distance * 1000:.1f} mm {bar.link_a})"
    if not points:
        return f"clear{in_bar}, the base moved {moved:.2f} m"
    worst = min(points, key=lambda p: p.distance)
    return (
        f"{-worst.distance * 1000:.1f} mm {worst.link_a}/{worst.link_b}{in_bar}, "
        f"base moved {moved:.2f} m"
    )


if __name__ == "__main__":
    main()

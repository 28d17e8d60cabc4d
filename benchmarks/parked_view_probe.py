"""How much of a pan-tilt camera's view the parked arms hide, look by look, on raw PyBullet.

Run: ``.venv/bin/python benchmarks/parked_view_probe.py NAME|MODULE [--step 15] [--rays 9]
[--reach 1.5]``.

The robot (a name of ``robot_zoo.CORPUS``, drafted as there, or a description module)
stands alone with every arm at its parking pose, and its head looks in a grid: the pan
every ``step`` degrees over its limits (at most 60 degrees each way), the tilt every
``step`` from its parking down to its limit (at most 60 degrees down). From each look a
``rays`` x ``rays`` fan of rays across the camera's fields of view, ``reach`` [m] long,
is cast with PyBullet's own kinematics and shapes; the table counts, per look, the rays
whose first hit is an arm's or hand's link. Why it is kept: the draft keeps a parked arm
out of the view straight ahead only, and Rollin' Justin's right thumb hid the kitchen's
mug from its head looking down at the counter, panned to it (issue 37, zoo34: 141 of
28 x 81 rays, in 18 of the 28 looks).
"""

from __future__ import annotations

import argparse
import math
import warnings
from pathlib import Path

import numpy as np
import pybullet

from robocram.robots.description import RobotDescription
from robocram.world import World

OUT = Path("/tmp/parked_view_probe_drafts")
NEAR = 0.06  # [m] rays start this far out: the head's own housing is not the view
MOST = math.radians(60.0)  # [rad] the pan each way and the tilt down, at most


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("robot", help="a zoo robot's name or a description module")
    parser.add_argument("--step", type=float, default=15.0, help="[degrees] between looks")
    parser.add_argument("--rays", type=int, default=9, help="per side of the view")
    parser.add_argument("--reach", type=float, default=1.5, help="[m] each ray's length")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    world = World()
    try:
        name = world.add_robot(_module(args.robot)).name
        desc = world.robot(name).description
        if desc.pan_tilt is None or not desc.cameras:
            raise SystemExit(f"{name} has no pan-tilt head with a camera: nothing to probe")
        for arm in desc.arms.values():
            world.set_joint_states(name, dict(arm.parking))
        _table(world, name, desc, args)
    finally:
        world.close()


def _module(robot: str) -> str:
    """The description module of a zoo robot's name (drafted as the zoo does), or ``robot``."""
    if robot.endswith(".py"):
        return robot
    from robot_zoo import CORPUS, _draft

    return _draft(next(r for r in CORPUS if r.name == robot), OUT)


def _steps(start: float, end: float, step: float) -> list[float]:
    """``start`` to ``end`` in equal steps no longer than ``step``, both ends included."""
    count = max(1, math.ceil(round(abs(end - start) / step, 6)))
    return [start + (end - start) * k / count for k in range(count + 1)]


def _table(world: World, name: str, desc: RobotDescription, args: argparse.Namespace) -> None:
    assert desc.pan_tilt is not None
    pan, tilt = desc.pan_tilt.pan_joint, desc.pan_tilt.tilt_joint
    client, body = world.physics.client(), world.object(name).body_id
    joints, links = {}, {}
    for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
        info = pybullet.getJointInfo(body, i, physicsClientId=client)
        joints[info[1].decode()], links[info[12].decode()] = i, i
        if info[1].decode() == tilt:
            tilt_limits = (info[8], info[9])
        if info[1].decode() == pan:
            pan_limits = (info[8], info[9])
    start = dict(desc.neck_parking)
    step = math.radians(args.step)
    pans = sorted(
        {
            *_steps(start.get(pan, 0.0), max(pan_limits[0], start.get(pan, 0.0) - MOST), step),
            *_steps(start.get(pan, 0.0), min(pan_limits[1], start.get(pan, 0.0) + MOST), step),
        }
    )
    down = _down_limit(desc, tilt, tilt_limits, client, body, joints, links)
    stop = start.get(tilt, 0.0) + max(-MOST, min(MOST, down - start.get(tilt, 0.0)))
    tilts = _steps(start.get(tilt, 0.0), stop, step)
    arm_links = {
        links[n]
        for key, arm in desc.arms.items()
        if key != desc.neck_arm
        for n in (*arm.links, *arm.hand_links)
        if n in links
    }
    print(f"{name}: rays (of {args.rays}x{args.rays}) meeting an arm, per look [degrees]")
    print("pan \\ tilt " + " ".join(f"{math.degrees(t):6.0f}" for t in tilts))
    total = blocked = 0
    for p in pans:
        row = []
        for t in tilts:
            pybullet.resetJointState(body, joints[pan], p, physicsClientId=client)
            pybullet.resetJointState(body, joints[tilt], t, physicsClientId=client)
            hits = _arm_hits(desc, arm_links, args, client, body, links)
            row.append(hits)
            total, blocked = total + hits, blocked + (hits > 0)
        print(f"{math.degrees(p):10.0f} " + " ".join(f"{h:6d}" for h in row))
    looks = len(pans) * len(tilts)
    print(f"total: {total} rays meet an arm, in {blocked} of {looks} looks")


def _optical(
    desc: RobotDescription, client: int, body: int, links: dict[str, int]
) -> tuple[np.ndarray, np.ndarray]:
    """The camera's optical frame (position, 3x3 rotation) in the map, from PyBullet."""
    camera = desc.cameras[0]
    added = {f.name: f for f in desc.extra_frames}
    frame = added.get(camera.frame)
    link = frame.parent if frame is not None else camera.frame
    state = pybullet.getLinkState(
        body, links[link], computeForwardKinematics=True, physicsClientId=client
    )
    offset = frame.pose if frame is not None else None
    position, orientation = state[4], state[5]
    if offset is not None:
        position, orientation = pybullet.multiplyTransforms(
            position, orientation, offset.position, offset.orientation
        )
    rotation = np.array(pybullet.getMatrixFromQuaternion(orientation)).reshape(3, 3)
    return np.asarray(position), rotation


def _down_limit(
    desc: RobotDescription,
    tilt: str,
    limits: tuple[float, float],
    client: int,
    body: int,
    joints: dict[str, int],
    links: dict[str, int],
) -> float:
    """The tilt's limit that turns the optical axis (z) towards the floor."""
    heights = []
    for end in limits:
        pybullet.resetJointState(body, joints[tilt], end, physicsClientId=client)
        heights.append(_optical(desc, client, body, links)[1][2, 2])
    return limits[0] if heights[0] < heights[1] else limits[1]


def _arm_hits(
    desc: RobotDescription,
    arm_links: set[int],
    args: argparse.Namespace,
    client: int,
    body: int,
    links: dict[str, int],
) -> int:
    """Rays from the camera as it looks now whose first hit is an arm's link."""
    camera = desc.cameras[0]
    eye, rotation = _optical(desc, client, body, links)
    starts, ends = [], []
    for a in np.linspace(-camera.horizontal_fov / 2, camera.horizontal_fov / 2, args.rays):
        for b in np.linspace(-camera.vertical_fov / 2, camera.vertical_fov / 2, args.rays):
            direction = rotation @ np.array((math.tan(a), math.tan(b), 1.0))
            direction /= np.linalg.norm(direction)
            starts.append(eye + direction * NEAR)
            ends.append(eye + direction * args.reach)
    hits = pybullet.rayTestBatch(starts, ends, physicsClientId=client)
    return sum(1 for h in hits if h[0] == body and h[1] in arm_links)


if __name__ == "__main__":
    main()

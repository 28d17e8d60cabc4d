"""Timings of the projection world: build, joints, visibility (rays vs render), state, copy.

Run: ``.venv/bin/python benchmarks/world_bench.py [repeats]``. Prints one line per figure,
and how often the ray and render visibility methods agree on a set of random scenes.
"""

from __future__ import annotations

import math
import random
import statistics
import sys
import time
from collections.abc import Callable

from robocram.tf import Pose
from robocram.world import Camera, World

ITEMS = ("pot", "mug", "mug", "bottle", "bowl", "plate", "cup", "cereal_box", "milk")


def _ms(fn: Callable[[], object], repeats: int) -> float:
    """Median wall time [ms] of ``fn`` over ``repeats`` runs."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def build() -> World:
    """Floor, PR2, a table and nine catalogue items on it (eleven objects besides the floor)."""
    world = World()
    world.bodies.add_floor()
    pr2 = world.add_robot("pr2")
    world.set_joint_states(pr2, {"torso_lift_joint": 0.3, "head_tilt_joint": 0.45})
    world.add_box("table", (0.7, 1.5, 0.75), Pose((1.4, 0, 0.375)), color=(0.6, 0.4, 0.2, 1))
    for i, kind in enumerate(ITEMS):
        y = -0.6 + 0.15 * i
        world.add_item(f"{kind}-{i}", kind, Pose((1.25 + 0.1 * (i % 2), y, 0.9)))
    return world


def agreement(world: World, scenes: int, seed: int = 1) -> tuple[float, float]:
    """Share of random camera views where both methods agree on ``visible`` (threshold 0.9),
    and the mean absolute difference of the fractions."""
    rng = random.Random(seed)
    targets = [o for o in world.objects() if o.type in ITEMS]
    agree, diffs = 0, []
    for _ in range(scenes):
        x, y, z = rng.uniform(-0.5, 0.6), rng.uniform(-1.2, 1.2), rng.uniform(0.9, 1.6)
        target = rng.choice(targets)
        tx, ty, tz = world.pose(target).position
        yaw = math.atan2(ty - y, tx - x) + rng.gauss(0, 0.3)
        pitch = math.atan2(z - tz, math.hypot(tx - x, ty - y)) + rng.gauss(0, 0.1)
        pose = Pose.from_xyz_rpy((x, y, z), (-math.pi / 2 - pitch, 0, yaw - math.pi / 2))
        camera = Camera(pose, math.radians(90), math.radians(73.7))
        ray = world.view.visibility_from(camera, target, "ray").fraction
        render = world.view.visibility_from(camera, target, "render").fraction
        agree += (ray >= 0.9) == (render >= 0.9)
        diffs.append(abs(ray - render))
    return agree / scenes, statistics.mean(diffs)


def main(repeats: int = 10) -> None:
    """Print the figures."""
    print(f"world_bench ({repeats} repeats, medians)")
    build_ms = _ms(lambda: build().close(), repeats)
    print(f"  build world (PR2 + table + 9 items)  {build_ms:8.2f} ms")
    with build() as world:
        pr2 = world.robot("pr2")
        values = {name: 0.0 for name in world.joint_states(pr2)}
        joints_ms = _ms(lambda: world.set_joint_states(pr2, values), repeats)
        print(f"  set_joint_states ({len(values)} joints)       {joints_ms:8.2f} ms")
        world.set_joint_states(pr2, {"torso_lift_joint": 0.3, "head_tilt_joint": 0.45})
        world.physics.simulate(1.0)
        for method in ("ray", "render"):
            vis_ms = _ms(lambda m=method: world.view.visible(pr2, "pot-0", method=m), repeats)  # type: ignore[misc]
            print(f"  visible ({method:6})                    {vis_ms:8.2f} ms")
        contact_ms = _ms(lambda: world.contacts.contact("pot-0", "table"), repeats)
        print(f"  contact query                        {contact_ms:8.3f} ms")
        coll_ms = _ms(lambda: world.contacts.collisions(pr2), repeats)
        print(f"  collisions(pr2) against all          {coll_ms:8.2f} ms")

        def round_trip() -> None:
            with world.snapshots.stored_state():
                world.remove("mug-1")
                world.set_pose("pot-0", Pose((0, 0, 3)))

        print(f"  stored_state round trip (+remove)    {_ms(round_trip, repeats):8.2f} ms")
        copy_ms = _ms(lambda: world.copy().close(), repeats)
        print(f"  copy()                               {copy_ms:8.2f} ms")
        stable_ms = _ms(lambda: world.physics.stable("pot-0"), max(1, repeats // 2))
        print(f"  stable(pot) (0.5 s simulated)        {stable_ms:8.2f} ms")
        sim_ms = _ms(lambda: world.physics.simulate(1.0), max(1, repeats // 2))
        factor = 1e3 / sim_ms
        print(f"  simulate(1.0)                        {sim_ms:8.2f} ms  real-time x{factor:.1f}")
        share, diff = agreement(world, 60)
        print(
            f"  ray vs render: agree on visible in {share:.0%} of 60 views, mean |diff| {diff:.3f}"
        )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)

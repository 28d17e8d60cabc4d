"""CPU time of one collision check of the PR2's right arm + torso in the kitchen.

Compares today's PyBullet broadphase check (``projection.collision_mode.colliding_pairs``)
with the coal scene (``motion.CollisionScene``), on seeded random configurations, with the
robot standing at the north counter (where about half of them collide). Prints
microseconds per check (``time.process_time``), the scene's build time and the agreement.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from robocram.motion import CollisionScene, joint_limits
from robocram.projection.collision_mode import colliding_pairs
from robocram.projection.projected_robot import ProjectedRobot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import RobotHandle


def main(samples: int = 300, repeats: int = 3) -> None:
    """Print the figures for ``samples`` configurations, each checked ``repeats`` times."""
    scene = kitchen_scene("pr2")
    world, robot = scene.world, scene.robot
    pose = world.pose(robot)
    world.set_pose(robot, Pose((pose.position[0], 1.35, 0.0), pose.orientation))
    desc = world.robot(robot).description
    joints = [desc.torso_joint or "", *desc.arms["right"].joints]
    limits = joint_limits(desc, joints)
    lower = np.array([max(lim.lower, -np.pi) for lim in limits])
    upper = np.array([min(lim.upper, np.pi) for lim in limits])
    qs = lower + np.random.default_rng(21).random((samples, len(joints))) * (upper - lower)

    start = time.process_time()
    for _ in range(5):
        coal_scene = CollisionScene.of(RobotHandle.of(world, robot), joints)
    build = (time.process_time() - start) / 5
    projected = ProjectedRobot.of(world, robot)
    links = set(world.link_names(robot))

    def per_check(fn) -> float:
        t = time.process_time()
        for _ in range(repeats):
            for q in qs:
                fn(q)
        return (time.process_time() - t) / (repeats * len(qs)) * 1e6

    def bullet(q):
        return colliding_pairs(projected, dict(zip(joints, q, strict=True)), set())

    print(f"PR2 right arm + torso at the kitchen counter, {samples} configurations")
    print(
        f"  scene build            {build * 1e3:8.1f} ms  ({coal_scene.geometry_count} geometries,"
        f" {coal_scene.pair_count} pairs)"
    )
    print(f"  pybullet broadphase    {per_check(bullet):8.1f} us/check")
    print(f"  coal is_free           {per_check(coal_scene.is_free):8.1f} us/check")
    print(f"  coal colliding         {per_check(coal_scene.colliding):8.1f} us/check")
    agree = sum(
        bool({p for p in coal_scene.colliding(q) if p[1] not in links}) == bool(bullet(q))
        for q in qs
    )
    print(f"  agreement (world)      {agree}/{samples}")
    print(
        f"  colliding (coal, self included) {sum(not coal_scene.is_free(q) for q in qs)}/{samples}"
    )


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:]))

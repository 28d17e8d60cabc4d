"""Work out the built-in robots' self-collision matrices and store them with their
descriptions (src/robocram/robots/builtin/self_collision/<name>.json).

Run it after changing a built-in robot's URDF, parking poses, fingers or allowed contacts:
a stored matrix whose digest no longer matches is not used (each process works it out
again, ~0.4 s), and tests/motion/test_motion_stored_self_collision.py fails until it is.
Usage: python tools/store_self_collision.py [ROBOT ...]   (default: every built-in robot)
"""

from __future__ import annotations

import sys

from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.motion.stored_self_collision import write_stored
from robocram.robots.builtin import builtin_names
from robocram.world import RobotHandle, World


def main(robots: list[str]) -> None:
    stored = set()
    for spec in robots or builtin_names():
        with World() as world:
            handle = world.add_robot(spec)
            name = handle.description.name  # an alias (hsr) names the same robot (hsrb)
            if name in stored:
                continue
            matrix, digest = SelfCollisionMatrix.worked_out(RobotHandle.of(world, handle.name))
        stored.add(name)
        path = write_stored(name, digest, matrix.to_data())
        print(f"{name}: {len(matrix.checked)} checked, {len(matrix.skipped)} skipped: {path}")


if __name__ == "__main__":
    main(sys.argv[1:])

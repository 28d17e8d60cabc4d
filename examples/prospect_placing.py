"""Choose where to put the mug by projecting both choices first, then do the better one.

CRAM projects plans to choose between parameters before the robot commits: here the PR2
prospects a transport of the mug to the table and one to the east counter, keeps the
one that succeeds with the least motion time, and performs it. Prospection leaves the
world exactly as it was, so the transport performed is the one that was projected.
Run: python examples/prospect_placing.py
"""

from __future__ import annotations

from robocram.designators import a
from robocram.plans import transport
from robocram.projection import prospect, simulated_robot
from robocram.scenes import kitchen_scene
from robocram.world import RobotHandle

PLACES = {"table": "table_top", "east counter": "counter_top_east"}


def main() -> str:
    """Prospect both places, perform the better; return the place chosen."""
    scene = kitchen_scene("pr2")
    targets = {
        name: a.location(on=("kitchen", link), for_="mug-1") for name, link in PLACES.items()
    }
    prospects = {
        name: prospect(
            RobotHandle.of(scene.world, scene.robot), lambda target=target: transport("mug", target)
        )
        for name, target in targets.items()
    }
    for name, seen in prospects.items():
        outcome = "succeeds" if seen.succeeded else f"fails: {type(seen.failure).__name__}"
        print(f"to the {name}: {outcome}, {seen.motion_time:.1f} s of motion")
    best = min(
        (name for name, seen in prospects.items() if seen.succeeded),
        key=lambda name: prospects[name].motion_time,
    )
    with simulated_robot(scene.world, scene.robot):
        transport("mug", targets[best])
    print(f"performed: the mug to the {best}, now at {scene.world.pose('mug-1').position}")
    scene.world.close()
    return best


if __name__ == "__main__":
    main()

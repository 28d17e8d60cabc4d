"""Draw the two costmaps of docs/locations.md: where Boxy sees the pot, where the PR2 reaches.

The visibility costmap is seed 001's scene (Boxy, a table, the pot that fell onto it); the
reachability costmap is the PR2 in the tabletop scene with the mug. Each picture shows the
weights (red, stronger is likelier) over a top-down render, the ten best cells circled,
and the robot standing at the first pose the designator yields.

Usage: ``python examples/costmap_pictures.py [out_dir=docs]``
"""

from __future__ import annotations

import sys
from pathlib import Path

from robocram.costmaps import CostmapLocations
from robocram.designators import LocationDesignator, a
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import World


def _draw(locations: CostmapLocations, designator: LocationDesignator, path: Path) -> Path:
    """Draw the designator's costmap with its robot standing at the first pose it yields."""
    costmap = locations.costmap(designator)
    robot = designator.properties[0][1]
    locations.world.set_pose(robot, next(locations.poses(designator)))
    return costmap.to_png(path, locations.world, pixels_per_cell=4)


def visibility_picture(path: Path) -> Path:
    """Boxy, seed 001's table and pot: the cells from which Boxy sees the pot."""
    with World() as world:
        world.bodies.add_floor()
        world.add_robot("boxy", pose=Pose((0.0, 0.0, 0.0)))
        world.add_box("table", (0.7, 1.5, 1.0), Pose((1.6, 0.0, 0.5)))
        world.add_box("shelf", (0.3, 0.6, 1.8), Pose((2.15, 0.75, 0.9)))
        world.add_item("pot", "pot", Pose((1.6, 0.0, 1.4)))
        world.physics.simulate(2.0)
        return _draw(CostmapLocations(world), a.location(visible_for="boxy", object="pot"), path)


def reachability_picture(path: Path) -> Path:
    """The PR2 in the tabletop scene: the cells from which it reaches the mug."""
    scene = tabletop_scene("pr2")
    try:
        locations = CostmapLocations(scene.world, size=3.0)
        return _draw(locations, a.location(reachable_for="pr2", object="mug-1"), path)
    finally:
        scene.world.close()


def main(out_dir: str = "docs") -> list[Path]:
    """Write both pictures into ``out_dir``; return their paths."""
    out = Path(out_dir)
    return [
        visibility_picture(out / "visibility_costmap.png"),
        reachability_picture(out / "reachability_costmap.png"),
    ]


if __name__ == "__main__":
    for written in main(*sys.argv[1:2]):
        print(written)

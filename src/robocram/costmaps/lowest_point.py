"""The lowest point of a robot at rest, in its base frame: worked out once per machine.

A reachability map's heights start at the robot's lowest point (a base frame held above
its feet), and the map's file is named by it, so the first map look-up of a process
needs it. Working it out reads every collision mesh of the robot (a PR2's take ~5 ms),
so it is kept on disk (:func:`~robocram.robots.disk_cache.kept_arrays`) by the model's
URDF text and each mesh file's path, size and modification time: a mesh changed in
place gives a new entry, a damaged entry is worked out again.
"""

from __future__ import annotations

import itertools
import os

import numpy as np

from robocram.robots import RobotModel
from robocram.robots.disk_cache import kept_arrays
from robocram.robots.link_centre import link_box
from robocram.robots.model_pose import resting_link_poses
from robocram.tf import Pose

__all__ = ["lowest_point"]

# the modules whose code works the point out: a change to any of them makes new entries
BUILT_BY = (__name__, "robocram.robots.link_centre", "robocram.robots.model_pose")


def lowest_point(model: RobotModel) -> float:
    """[m] The lowest corner of any link's box in the base frame, at most 0 (kept with
    the model (``model.derived(lowest_point)``) and on disk)."""
    kept = kept_arrays(
        "lowest-points", f"{model.to_urdf()}\n{_mesh_stamps(model)}", BUILT_BY,
        lambda: {"lowest": np.array(worked_out(model))},
    )  # fmt: skip
    return float(kept["lowest"])


def worked_out(model: RobotModel) -> float:
    """:func:`lowest_point` from the model and its meshes, nothing kept read."""
    lowest = 0.0
    poses = resting_link_poses(model)
    for name, link in model.links.items():
        box = link_box(link)
        if box is None:
            continue
        pose = poses[name]
        (x0, y0, z0), (x1, y1, z1) = box
        for corner in itertools.product((x0, x1), (y0, y1), (z0, z1)):
            lowest = min(lowest, (pose * Pose(corner)).position[2])
    return lowest


def _mesh_stamps(model: RobotModel) -> str:
    """Each collision mesh file's path, size and modification time (``missing`` when it
    cannot be read: then it counts as no box, as :func:`link_box` counts it)."""
    files = sorted(
        {c.geometry.filename for link in model.links.values() for c in link.collisions
         if c.geometry.kind == "mesh"}
    )  # fmt: skip
    lines = []
    for file in files:
        try:
            stat = os.stat(file)
        except OSError:
            lines.append(f"{file} missing")
            continue
        lines.append(f"{file} {stat.st_size} {stat.st_mtime_ns}")
    return "\n".join(lines)

"""Where a hand's finger pads end along its approach: behind its tool frame, or past it.

A grasp puts the tool frame where the fingers should close, so a hand is drawn (or
drafted) with its tool frame between its pads. A drafted tool frame need not be: Tracy's
Robotiq 85 pads end 18-36 mm behind its tool frame, so a rim grasp 2 cm below a bowl's
rim closed on nothing over the wall. Such a hand gets deep rim grasps
(``grasp_model._rim``); a hand whose pads reach its tool frame (the PR2's, Boxy's, HSR's,
Fetch's) does not, so its grasps and plans stay as they were.

Read from the finger links' collision shapes (a mesh's vertices, a primitive's corners;
``link_centre.link_points``) in the tool frame, at :data:`STROKE` points of the fingers'
travel from open to closed: how far along the approach axis the fingers reach at most
(a Robotiq's pads swing forward as they close, HSR's back as they open), and the
farthest of those counts.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from robocram.robots import RobotDescription
from robocram.robots.disk_cache import file_key, kept_arrays
from robocram.robots.link_centre import link_points
from robocram.robots.model_pose import link_pose

STROKE = (0.0, 0.25, 0.5, 0.75, 1.0)  # the hand this far open: where the pads are read
BUILT_BY = (
    __name__, "robocram.robots.link_centre", "robocram.robots.model_pose",
    "robocram.robots.mimic", "robocram.robots.robot_model", "robocram.tf.pose",
    "robocram.tf.quaternion",
)  # fmt: skip


def pads_behind(desc: RobotDescription, arm: str, approach: tuple[float, float, float]) -> float:
    """How far [m] behind ``arm``'s tool frame (against ``approach``, a unit axis in the
    tool frame) its fingers end, wherever they are over their stroke: negative when they
    reach past it; 0.0 when no finger has a readable shape (nothing to say it is not
    where the fingers close). Kept on disk (``disk_cache``): reading it took ~9 ms a PR2
    hand, nine times the rest of the hand."""
    spec = desc.arms[arm]
    gripper, model = spec.gripper, desc.model
    if model is None or gripper is None or gripper.is_suction or not spec.gripper_links:
        return 0.0
    meshes = sorted(
        {
            c.geometry.filename
            for link in spec.gripper_links
            for c in model.link(link).collisions
            if c.geometry.kind == "mesh"
        }
    )
    stroke = [sorted(gripper.at(fraction).items()) for fraction in STROKE]
    key = "\n".join(
        (
            model.to_urdf(),
            spec.tool_frame,
            repr(spec.gripper_links),
            repr(stroke),
            repr(approach),
            *(file_key(Path(m)) if Path(m).is_file() else m for m in meshes),
        )
    )
    kept = kept_arrays(
        "pad-reach", key, BUILT_BY, lambda: {"behind": np.array(_measured(desc, arm, approach))}
    )
    return float(kept["behind"])


def _measured(desc: RobotDescription, arm: str, approach: tuple[float, float, float]) -> float:
    spec = desc.arms[arm]
    gripper, model = spec.gripper, desc.model
    assert gripper is not None and model is not None  # pads_behind checked both
    shapes = [(link, link_points(model.link(link))) for link in spec.gripper_links]
    readable = [(link, points) for link, points in shapes if points is not None]
    if not readable:
        return 0.0
    tool = link_pose(model, spec.tool_frame).inverse()
    axis = np.asarray(approach)
    farthest = -np.inf
    for fraction in STROKE:
        joints = gripper.at(fraction)
        for link, points in readable:
            pose = (tool * link_pose(model, link, joints)).matrix()
            ahead = (points @ pose[:3, :3].T + pose[:3, 3]) @ axis
            farthest = max(farthest, float(ahead.max()))
    return -farthest

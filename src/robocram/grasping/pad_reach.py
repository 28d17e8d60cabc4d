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

import numpy as np

from robocram.kinematics import forward_kinematics
from robocram.robots import RobotDescription
from robocram.robots.link_centre import link_points

STROKE = (0.0, 0.25, 0.5, 0.75, 1.0)  # the hand this far open: where the pads are read


def pads_behind(desc: RobotDescription, arm: str, approach: tuple[float, float, float]) -> float:
    """How far [m] behind ``arm``'s tool frame (against ``approach``, a unit axis in the
    tool frame) its fingers end, wherever they are over their stroke: negative when they
    reach past it; 0.0 when no finger has a readable shape (nothing to say it is not
    where the fingers close)."""
    spec = desc.arms[arm]
    gripper = spec.gripper
    if desc.model is None or gripper is None or gripper.is_suction:
        return 0.0
    shapes = [(link, link_points(desc.model.link(link))) for link in spec.gripper_links]
    readable = [(link, points) for link, points in shapes if points is not None]
    if not readable:
        return 0.0
    tool = forward_kinematics(desc, {}, spec.tool_frame).inverse()
    axis = np.asarray(approach)
    farthest = -np.inf
    for fraction in STROKE:
        joints = gripper.at(fraction)
        for link, points in readable:
            pose = (tool * forward_kinematics(desc, joints, link)).matrix()
            ahead = (points @ pose[:3, :3].T + pose[:3, 3]) @ axis
            farthest = max(farthest, float(ahead.max()))
    return -farthest

"""Whether a drafted robot's camera sees where its arms reach; else the camera an arm carries.

A camera that cannot tilt (a head that only pans, as Baxter's, or none turning it) sees
down to the lower edge of its view and no nearer. Where, straight ahead at the height of
the picking arm's shoulder, that edge lies beyond :data:`SEEN_REACH_SHARE` of the arm's
reach, no table in its view is in reach (a table lies lower, so farther out still): the
scenes put a mug nowhere both seen and reachable (Baxter's head camera, 33 degrees down at
most, sees 1.12 m from the shoulder there, its arm reaching 1.14 m). A camera named so on
that arm (its wrist camera) is drafted instead: the arm aims it where it reaches. Asked of
a fixed robot only: one that moves stands back to see (Kevin's level head camera sees its
mug from where its pick-up stands).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from robocram.robots.arm_envelope import arm_reach
from robocram.robots.description import ArmDescription
from robocram.robots.description_check import infer_arm
from robocram.robots.draft.camera_sensors import CameraSensor, sensor_for
from robocram.robots.draft.cameras import DEFAULT_VFOV, camera_frames, find_neck, looking_axis
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree

SEEN_REACH_SHARE = 0.85  # of the arm's reach: the farthest a mug in view may lie from the
# shoulder (the scenes' raised tables allow as much: placement.RAISED_REACH_SHARE)


def arm_camera_instead(
    tree: ModelTree, arms: Mapping[str, ArmDescription], sensors: Sequence[CameraSensor] = ()
) -> tuple[str, str] | None:
    """The camera link on the picking arm (the right-most: smallest shoulder y, as the
    scenes pick) and why, where the best named camera cannot see that arm's reach
    (:func:`sees_reach`); None where it can, or no named camera rides on that arm."""
    hands = [arm.end_effector_link for arm in arms.values()]
    frames = camera_frames(tree, hands)
    if not frames or not arms:
        return None
    full = {key: infer_arm(arm, tree.model) for key, arm in arms.items()}
    poses = link_poses(tree.model)
    turning = {key: arm for key, arm in full.items() if arm.joints}
    if not turning:
        return None
    picking = min(
        turning.values(),
        key=lambda a: (poses[tree.model.joints[a.joints[0]].child].position[1], a.name),
    )
    if _carried(tree, frames[0], picking) or sees_reach(tree, frames[0], picking, sensors):
        return None
    carried = [f for f in frames if _carried(tree, f, picking)]
    if not carried:
        return None
    why = (
        f"camera frame on the {picking.name} arm: {frames[0]} cannot tilt and sees, at the "
        f"shoulder's height, no nearer than {SEEN_REACH_SHARE} of the arm's reach"
    )
    return carried[0], why


def _carried(tree: ModelTree, frame: str, arm: ArmDescription) -> bool:
    return bool({j.name for j in tree.movable_ancestors(frame)} & set(arm.joints))


def sees_reach(
    tree: ModelTree, frame: str, arm: ArmDescription, sensors: Sequence[CameraSensor] = ()
) -> bool:
    """Whether the camera ``frame`` sees, straight ahead at ``arm``'s shoulder height,
    within :data:`SEEN_REACH_SHARE` of its reach; true for a camera that tilts (a pan-tilt
    unit, a neck arm) or whose axes say nothing about where it looks."""
    neck = find_neck(tree, frame, None)
    if neck.pan_tilt is not None or neck.arm_joints:
        return True
    poses = link_poses(tree.model)
    camera = poses[frame]
    axes = camera.matrix()[:3, :3]
    which = looking_axis(axes, "optical" in frame.lower())
    if which is None:
        return True
    axis = axes[:, 2] if which == "z" else axes[:, 0]
    sensor = sensor_for(frame, tree.rigid_group(frame), sensors)
    half = (DEFAULT_VFOV if sensor is None else sensor.vertical_fov) / 2
    down = math.asin(max(-1.0, min(1.0, -float(axis[2])))) + half
    shoulder = poses[tree.model.joints[arm.joints[0]].child].position
    drop = camera.position[2] - shoulder[2]
    if drop <= 0.0:
        return True  # it looks from below the shoulder: nothing here bounds it
    if down <= 0.0:
        return False
    down = min(down, math.pi / 2 - 1e-6)  # straight down: it sees what lies beneath it
    heading = np.asarray((float(axis[0]), float(axis[1])))
    heading = heading / max(float(np.linalg.norm(heading)), 1e-9)
    seen = np.asarray(camera.position[:2]) + heading * drop / math.tan(down)
    out = float(np.linalg.norm(seen - np.asarray(shoulder[:2])))
    return out <= SEEN_REACH_SHARE * arm_reach(tree.model, arm)

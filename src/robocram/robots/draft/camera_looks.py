"""The body camera's views a parked arm must keep out of: as the plans look, not only ahead.

The plans turn a pan-tilt head to what they look for: down at a counter or a table top,
panned to the item, as far as the tilt's limit where the item lies low. A parked arm kept
out of the straight-ahead view alone hung before Rollin' Justin's head camera when it
looked down at the kitchen's counter, panned to the mug (its right thumb hid the mug).
So the view is the camera's from the neck's parking and from every look in a grid: the
tilt turned down in steps to its limit (at most :data:`TILT_DOWN`), each panned every
:data:`STEP` each way (at most :data:`PAN`) within limits. A pan that turns the arm too
(Centauro's waist) turns it with the camera: there only the tilt's looks count.
"""

from __future__ import annotations

import math

from robocram.robots.description import RobotDescription
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.draft.parking import joint_range
from robocram.robots.draft.stowing import CameraView
from robocram.tf import Pose

TILT_DOWN = math.radians(60.0)  # [rad] below the parked tilt, at most: counters, not feet
PAN = math.radians(60.0)  # [rad] each way from the parked pan, at most
STEP = math.radians(15.0)  # [rad] between the looks checked
NUDGE = 0.1  # [rad] a tilt's turn each way that says which way is down


def camera_view(tree: ModelTree, desc: RobotDescription, arm: str) -> CameraView | None:
    """The first camera's view in the root link over the looks ``arm`` parked must keep
    clear of (see the module docstring), or None (no camera, or one an arm carries: its
    parking aims it)."""
    if not desc.cameras:
        return None
    camera = desc.cameras[0]
    added = {f.name: f for f in desc.extra_frames}
    spec = added.get(camera.frame)
    link = spec.parent if spec is not None else camera.frame
    if link not in tree.model.links or any(
        link in tree.subtree_links(other.end_effector_link) or link == other.end_effector_link
        for key, other in desc.arms.items()
        if key != desc.neck_arm
    ):
        return None
    offset = spec.pose if spec is not None else Pose()
    parked = dict(desc.neck_parking)
    looks = tuple(
        link_poses(tree.model, {**parked, **turned})[link] * offset
        for turned in _looks(tree, desc, arm, link, offset)
    )
    pose = link_poses(tree.model, parked)[link] * offset
    return CameraView(pose, camera.horizontal_fov, camera.vertical_fov, looks=looks)


def _looks(
    tree: ModelTree, desc: RobotDescription, arm: str, link: str, offset: Pose
) -> list[dict[str, float]]:
    """The pan and tilt values of each look besides the parked one (none without a
    pan-tilt head)."""
    if desc.pan_tilt is None:
        return []
    pan, tilt = desc.pan_tilt.pan_joint, desc.pan_tilt.tilt_joint
    parked = dict(desc.neck_parking)
    tilts = _steps(parked.get(tilt, 0.0), _down_limit(tree, parked, tilt, link, offset), TILT_DOWN)
    base = desc.arms[arm].base_link
    turned = tree.model.joints[pan].child
    turns_arm = base is not None and (base == turned or base in tree.subtree_links(turned))
    start = parked.get(pan, 0.0)
    lower, upper = joint_range(tree.model, pan)
    pans = [start] if turns_arm else _steps(start, lower, PAN)[::-1] + _steps(start, upper, PAN)
    looks = [{pan: p, tilt: t} for t in tilts for p in sorted(set(pans))]
    return [look for look in looks if look != {pan: start, tilt: parked.get(tilt, 0.0)}]


def _steps(start: float, limit: float, most: float) -> list[float]:
    """``start`` and every :data:`STEP` from it towards ``limit``, at most ``most`` away,
    the last one at the limit or the most (to 3 decimals)."""
    end = start + max(-most, min(most, limit - start))
    count = max(1, math.ceil(round(abs(end - start) / STEP, 6)))
    return [round(start + (end - start) * k / count, 3) for k in range(count + 1)]


def _down_limit(
    tree: ModelTree, parked: dict[str, float], tilt: str, link: str, offset: Pose
) -> float:
    """The ``tilt``'s limit on the side that turns the camera's optical axis (z) down,
    towards the floor (judged a small turn each way from the parked tilt)."""
    start = parked.get(tilt, 0.0)

    def axis_height(value: float) -> float:
        pose = link_poses(tree.model, {**parked, tilt: value})[link] * offset
        return float(pose.matrix()[2, 2])

    lower, upper = joint_range(tree.model, tilt)
    return upper if axis_height(start + NUDGE) < axis_height(start - NUDGE) else lower

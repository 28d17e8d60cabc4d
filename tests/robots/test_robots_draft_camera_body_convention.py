"""A camera frame not named optical, tilted steeply down, is read by the ROS body convention.

Tracy's ``camera_link`` is pitched 72 degrees: its x looks 72 degrees down onto the
workspace, its z 18 degrees up over it. The draft took z ("optical: z looks forward");
a frame named like a camera but not ``optical`` whose x looks ahead and down while its z
looks up now gets an optical frame added along its x. A frame named optical keeps its z.
Judged from the frames' poses (the URDF's rpy, worked out here): the drafted optical axis.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.robots import RobotModel
from robocram.robots.draft.cameras import find_camera
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree

URDF = """<robot name="pole"><link name="base_link"/><link name="{name}"/>
<joint name="cam" type="fixed"><parent link="base_link"/>
<child link="{name}"/><origin xyz="0 0 1.5" rpy="0 {pitch} 0"/></joint>
</robot>"""
PITCH = math.radians(72.0)


def _optical_axis(name: str) -> tuple[str, np.ndarray]:
    model = RobotModel.from_string(URDF.format(name=name, pitch=PITCH))
    camera = find_camera(ModelTree(model), [], None)
    assert camera is not None
    poses = link_poses(model)
    frame = poses[name] * camera.added.pose if camera.added is not None else poses[name]
    return camera.frame, frame.matrix()[:3, 2]


def test_a_camera_link_tilted_down_looks_along_its_x() -> None:
    frame, axis = _optical_axis("camera_link")
    assert frame == "camera_link_optical"
    # the link's x, turned 72 degrees down about y: (cos 72, 0, -sin 72)
    assert axis == pytest.approx((math.cos(PITCH), 0.0, -math.sin(PITCH)), abs=1e-6)


def test_an_optical_frame_tilted_so_keeps_its_z() -> None:
    frame, axis = _optical_axis("camera_optical_frame")
    assert frame == "camera_optical_frame"
    assert axis == pytest.approx((math.sin(PITCH), 0.0, math.cos(PITCH)), abs=1e-6)

"""The draft's camera doubt and the check's "looks ahead" use one threshold (issue 37).

A camera tilted 50 degrees down (its z has an x share of 0.64) was drafted with "neither
its z nor its x looks forward" while `robot check` said "z looks ahead": the draft asked
for 0.7, the check for 0.5.
"""

from __future__ import annotations

import math

import pytest

from robocram.robots import RobotModel
from robocram.robots.draft.cameras import LOOKS_AHEAD, find_camera
from robocram.robots.draft.link_poses import link_poses
from robocram.robots.draft.model_tree import ModelTree

URDF = """<robot name="tilted"><link name="base_link"/><link name="head_camera_optical_frame"/>
<joint name="cam" type="fixed"><parent link="base_link"/>
<child link="head_camera_optical_frame"/><origin xyz="0.1 0 1.2" rpy="{r} {p} {y}"/></joint>
</robot>"""


def _camera(down: float) -> tuple[float, str | None]:
    """The drafted camera of an optical frame (z ahead) tilted ``down`` [rad]: its z's x
    share in the root and the draft's doubt."""
    rpy = (-math.pi / 2 - down, 0.0, -math.pi / 2)
    model = RobotModel.from_string(URDF.format(r=rpy[0], p=rpy[1], y=rpy[2]))
    camera = find_camera(ModelTree(model), [], None)
    assert camera is not None
    share = float(link_poses(model)[camera.frame].matrix()[0, 2])
    return share, camera.doubt


@pytest.mark.parametrize("degrees", [0.0, 40.0, 50.0, 58.0])
def test_a_camera_the_check_counts_as_ahead_is_not_doubted(degrees: float) -> None:
    share, doubt = _camera(math.radians(degrees))
    assert share == pytest.approx(math.cos(math.radians(degrees)), abs=1e-6)
    assert share >= LOOKS_AHEAD and doubt is None


def test_a_camera_looking_down_steeply_is_doubted_with_the_checks_numbers() -> None:
    share, doubt = _camera(math.radians(70.0))
    assert share < LOOKS_AHEAD
    assert doubt is not None and f"x share {share:.2f}" in doubt and str(LOOKS_AHEAD) in doubt

"""A robot whose URDF names no camera gets one on the likely link (issue 37).

Seven robots of the zoo stopped at `robot check` with "no camera is described", the fix
naming the link the draft could have used itself. The draft now puts the camera there, as
``--camera LINK`` would, with an optical frame aimed ahead and down where the link's own
axes do not look ahead, and a doubt saying so. Drafts of URDFs that name a camera keep
their text (kept drafts from before this change).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from robocram.robot_check import check_robot, description_from
from robocram.robots import DraftDescription, RobotModel, draft_description
from robocram.robots.draft.cameras import AIM_DOWN, LOOKS_AHEAD, aimed_optics, likely_camera_link
from robocram.robots.draft.hands import find_hands
from robocram.robots.draft.model_tree import ModelTree
from tests import drafts

DATA = Path(__file__).resolve().parents[1] / "data"
JUSTIN = DATA / "zoo" / "rollin_justin" / "rollin_justin.urdf"


@dataclass(frozen=True)
class Justin:
    """Rollin' Justin's draft, its text and the module written from it."""

    drafted: DraftDescription
    text: str
    module: Path


@pytest.fixture(scope="module")
def justin(tmp_path_factory: pytest.TempPathFactory) -> Justin:
    """Drafted once for the module's tests (each drafted it again, ~0.7 s CPU)."""
    module = tmp_path_factory.mktemp("justin") / "rollin_justin.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted = draft_description(JUSTIN)
    text = drafted.source(module)
    module.write_text(text, "utf-8")
    return Justin(drafted, text, module)


def test_a_urdf_naming_no_camera_gets_one_on_the_likely_link(justin: Justin) -> None:
    drafted = justin.drafted
    desc = drafted.description
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = RobotModel.from_file(JUSTIN, (), missing_packages_as_boxes=True)
    tree = ModelTree(model)
    likely = likely_camera_link(tree, [h.end_effector_link for h in find_hands(tree)])
    assert likely == "head2"  # past both head joints, not head1 between them
    (camera,) = desc.cameras
    added = next(f for f in desc.extra_frames if f.name == camera.frame)
    assert (added.name, added.parent) == ("head2_optical", "head2")
    assert desc.pan_tilt is not None
    assert (desc.pan_tilt.pan_joint, desc.pan_tilt.tilt_joint) == ("head1_joint", "head2_joint")
    assert "inferred" in drafted.doubts["cameras.0"]
    assert "--camera LINK" in drafted.doubts["cameras.0"]


def test_the_drafted_text_says_the_camera_was_inferred(justin: Justin) -> None:
    text = justin.text
    assert "# TODO doubt: inferred, not read from the URDF: the camera is put on 'head2'" in text
    assert 'frame="head2_optical"' in text


def test_the_inferred_camera_passes_the_camera_checks(justin: Justin) -> None:
    module = justin.module
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(description_from(str(module)))
    names = {r.name: r for r in card.results}
    assert "camera" not in names  # part presence: a camera is described
    ahead = names["camera head2_optical: looks ahead"]
    assert ahead.passed, ahead.detail
    assert names["look"].passed and names["detect"].passed, card.render()


@pytest.mark.parametrize("rpy", [(0.0, 0.0, 0.0), (0.3, -1.2, 2.0), (math.pi, 0.4, -0.7)])
def test_an_aimed_optical_frame_looks_ahead_and_down_whatever_the_link(
    rpy: tuple[float, float, float],
) -> None:
    """Checked by composing rotation matrices, not by the draft's own quaternion path."""
    roll, pitch, yaw = rpy
    rx = np.array(
        [[1, 0, 0], [0, math.cos(roll), -math.sin(roll)], [0, math.sin(roll), math.cos(roll)]]
    )
    ry = np.array(
        [[math.cos(pitch), 0, math.sin(pitch)], [0, 1, 0], [-math.sin(pitch), 0, math.cos(pitch)]]
    )
    rz = np.array(
        [[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0], [0, 0, 1]]
    )
    link = rz @ ry @ rx
    optical = link @ aimed_optics(link).matrix()[:3, :3]
    z, x = optical[:, 2], optical[:, 0]
    assert z == pytest.approx((math.cos(AIM_DOWN), 0.0, -math.sin(AIM_DOWN)), abs=1e-5)
    assert x == pytest.approx((0.0, -1.0, 0.0), abs=1e-5)  # the image's x: the robot's right
    assert z[0] >= LOOKS_AHEAD


@pytest.mark.parametrize("name", ["iai_donbot", "kevin"])
def test_a_urdf_naming_a_camera_is_drafted_as_before(name: str) -> None:
    """The kept texts were drafted before inferred cameras existed (Kevin's tool frame since
    the approach follows the fingers, not the links on its wrist)."""
    module = DATA / "drafts" / f"{name}.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        text = drafts.drafted(DATA / "zoo" / name / f"{name}.urdf").source(module)
    assert text == (DATA / "drafts" / f"{name}.py.txt").read_text("utf-8")

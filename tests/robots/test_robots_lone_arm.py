"""Issue 37: a lone arm has a fixed base; arms without fingers on a waist (Centauro) get
suction grippers, the waist left to the head."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from robocram.robots import GripperDescription, RobotModel
from robocram.robots import example_robot_data_folder as erd
from robocram.robots.draft.base_drive import find_base_drive
from robocram.robots.draft.model_tree import ModelTree
from tests.drafts import drafted

ZOO = Path(__file__).resolve().parents[1] / "data" / "zoo"


def _drive(urdf: Path) -> str:
    model = RobotModel.from_file(urdf, (), missing_packages_as_boxes=True)
    return find_base_drive(ModelTree(model)).base_type


@pytest.mark.parametrize(
    ("urdf", "drive"),
    [
        (erd() / "kinova_description" / "robots" / "kinova.urdf", "fixed"),  # one chain
        (erd() / "xarm_description" / "urdf" / "xarm7.urdf", "fixed"),  # root 'world'
        (ZOO / "tracy" / "tracy.urdf", "fixed"),  # a two-arm station on 'world'
        (ZOO / "armar6" / "armar6.urdf", "holonomic"),  # 'world' over its platform
        (ZOO / "mabi_mobile" / "mabi_mobile.urdf", "holonomic"),  # one chain on a platform
    ],
    ids=lambda v: v.stem if isinstance(v, Path) else v,
)
def test_a_lone_arm_is_fixed_and_a_platform_is_not(urdf: Path, drive: str) -> None:
    assert _drive(urdf) == drive


@pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")
def test_centauro_gets_two_suction_arms_below_its_waist() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        draft = drafted(erd() / "centauro_description" / "urdf" / "centauro.urdf")
    desc = draft.description
    assert set(desc.arms) == {"left", "right"}
    for arm in desc.arms.values():
        assert arm.gripper == GripperDescription.suction()
        assert "torso_yaw" not in arm.joints and "torso_yaw" not in arm.parking
        assert f"arms.{arm.name}.gripper" in draft.doubts
    assert desc.pan_tilt is not None and desc.pan_tilt.pan_joint == "torso_yaw"

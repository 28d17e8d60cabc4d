"""Robots: URDF models, typed robot descriptions, built-in robots and interface facts.

The description drafter (:mod:`robocram.robots.draft`) is loaded when first asked for: it
pulls pinocchio and coal in, which a script that only loads a robot does not need yet.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from robocram.robots.description import (
    ArmDescription,
    BaseType,
    CameraDescription,
    LoadedDescription,
    PanTiltDescription,
    RobotDescription,
)
from robocram.robots.description_source import is_description_spec
from robocram.robots.errors import (
    DescriptionCheckError,
    DescriptionError,
    DescriptionUsageError,
    GripperDescriptionError,
    JointValueError,
    LimitValueError,
    MissingMeshWarning,
    PackageNotFoundError,
    PackagePathError,
    SrdfError,
    UrdfError,
)
from robocram.robots.example_robot_data import example_robot_data_folder
from robocram.robots.findings import DescriptionWarning, Finding
from robocram.robots.fixed_merge import MergedModel, merge_fixed_links
from robocram.robots.gripper import GripperDescription, GripperJoint
from robocram.robots.interface_facts import install_description
from robocram.robots.loading import load_description
from robocram.robots.mimic import mimic_followers
from robocram.robots.model_additions import BoxSpec, FrameSpec, JointCoupling
from robocram.robots.model_pose import joint_transform, link_pose
from robocram.robots.model_split import ModelPart, SplitModel, split_model
from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Geometry, Inertial, Joint, Link, Mimic

if TYPE_CHECKING:
    from robocram.robots.draft.draft_description import DraftDescription, draft_description

__all__ = [
    "ArmDescription",
    "BaseType",
    "BoxSpec",
    "CameraDescription",
    "DescriptionCheckError",
    "DescriptionError",
    "DescriptionUsageError",
    "DescriptionWarning",
    "DraftDescription",
    "Finding",
    "FrameSpec",
    "Geometry",
    "GripperDescription",
    "GripperDescriptionError",
    "GripperJoint",
    "Inertial",
    "Joint",
    "JointCoupling",
    "JointValueError",
    "LimitValueError",
    "Link",
    "LoadedDescription",
    "MergedModel",
    "Mimic",
    "MissingMeshWarning",
    "ModelPart",
    "PackageNotFoundError",
    "PackagePathError",
    "PanTiltDescription",
    "RobotDescription",
    "RobotModel",
    "SplitModel",
    "SrdfError",
    "UrdfError",
    "draft_description",
    "example_robot_data_folder",
    "install_description",
    "is_description_spec",
    "joint_transform",
    "link_pose",
    "load_description",
    "merge_fixed_links",
    "mimic_followers",
    "split_model",
]


def __getattr__(name: str) -> object:
    """The drafter's names, imported on first use (see the module's docstring)."""
    if name in ("DraftDescription", "draft_description"):
        import robocram.robots.draft.draft_description as drafting

        return getattr(drafting, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

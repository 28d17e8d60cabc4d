"""Typed robot descriptions: what CRAM's robot interface predicates say, as frozen values.

A :class:`RobotDescription` names a URDF and the parts of the robot plans talk about: base
and odom frames, torso, any number of named arms, cameras, a pan-tilt unit, and frames or
collision boxes to add to the model in code. ``load_description`` checks it against the URDF
and fills ``model``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocram.tf import Pose

if TYPE_CHECKING:
    from robocram.robots.robot_model import RobotModel


@dataclass(frozen=True)
class ArmDescription:
    """One kinematic chain that ends in a tool frame: an arm, or a neck that points a camera.

    Leave ``joints`` (and ``links``) empty to infer them from ``base_link`` to
    ``end_effector_link``. Joint values in ``parking`` and ``carrying`` are [rad] or [m].
    """

    name: str
    end_effector_link: str
    tool_frame: str
    base_link: str | None = None
    joints: tuple[str, ...] = ()
    links: tuple[str, ...] = ()
    gripper_joints: tuple[str, ...] = ()
    gripper_links: tuple[str, ...] = ()
    hand_links: tuple[str, ...] = ()
    parking: Mapping[str, float] = field(default_factory=dict)
    carrying: Mapping[str, float] = field(default_factory=dict)
    side: str | None = None  # "left" | "right": the side CRAM's two-armed motions call it


@dataclass(frozen=True)
class CameraDescription:
    """A camera: its optical frame (z forward, x right, y down) and where the torso can hold it."""

    frame: str
    minimal_height: float  # [m] over the floor
    maximal_height: float  # [m] over the floor
    horizontal_fov: float  # [rad]
    vertical_fov: float  # [rad]
    name: str = "camera"


@dataclass(frozen=True)
class PanTiltDescription:
    """The links and joints of a pan-tilt head."""

    pan_link: str
    tilt_link: str
    pan_joint: str
    tilt_joint: str


@dataclass(frozen=True)
class FrameSpec:
    """A frame added to the model in code, as a child of ``parent`` by a fixed joint."""

    name: str
    parent: str
    pose: Pose  # of the new frame in ``parent``


@dataclass(frozen=True)
class BoxSpec:
    """A collision box added to the model in code, on a new link fixed to ``parent``."""

    name: str
    parent: str
    pose: Pose  # of the box centre in ``parent``
    size: tuple[float, float, float]  # [m] full extents along x, y, z


@dataclass(frozen=True)
class RobotDescription:
    """What plans need to know about one robot, beside its URDF.

    ``urdf`` is a file path or a ``package://pkg/path`` URI; ``package_paths`` are extra
    folders searched for ``package://`` URIs. ``model`` is ``None`` (or a model to use
    instead of reading ``urdf``) until ``load_description`` has parsed the URDF and
    checked every name against it, which gives a :class:`LoadedDescription`.
    """

    name: str
    urdf: str | Path
    base_frame: str
    odom_frame: str = "odom"
    torso_link: str | None = None
    torso_joint: str | None = None
    arms: Mapping[str, ArmDescription] = field(default_factory=dict)
    cameras: tuple[CameraDescription, ...] = ()
    pan_tilt: PanTiltDescription | None = None
    neck_arm: str | None = None
    neck_parking: Mapping[str, float] = field(default_factory=dict)
    extra_frames: tuple[FrameSpec, ...] = ()
    extra_boxes: tuple[BoxSpec, ...] = ()
    package_paths: tuple[Path, ...] = ()
    flying: bool = False
    model: RobotModel | None = None

    def arm_called(self, word: str) -> str:
        """The key of the arm ``word`` names: its own name, or the ``side`` it is on.

        Motions say ``left_target`` or ``gripper="left"`` for two-armed robots whatever
        their arms are called; a word naming no arm comes back unchanged, for the caller
        to report with the arms it knows.
        """
        if word in self.arms:
            return word
        return next((key for key, arm in self.arms.items() if arm.side == word), word)

    def resources(self) -> tuple[str, ...]:
        """The motion table resources this robot has a process module for, in start order."""
        if self.flying:
            return ("flying", "distance_sensor", *(("perception",) if self.cameras else ()))
        found = ["navigation"]
        if self.torso_joint is not None:
            found.append("torso")
        if self.cameras:
            found.append("perception")
            if self.pan_tilt is not None or self.neck_arm is not None:
                found.append("ptu")
        if any(name != self.neck_arm for name in self.arms):
            found += ["grippers", "arms"]
        return tuple(found)


@dataclass(frozen=True)
class LoadedDescription(RobotDescription):
    """A description checked against its URDF: ``model`` is always the parsed model.

    Only ``load_description`` makes one; code that needs the model takes this type, so
    it never has to test ``model`` for None.
    """

    model: RobotModel = field(kw_only=True)

    @classmethod
    def checked(
        cls, desc: RobotDescription, model: RobotModel, **changes: Any
    ) -> LoadedDescription:
        """``desc`` with ``model`` and ``changes`` applied (for ``load_description``)."""
        values = {f.name: getattr(desc, f.name) for f in fields(RobotDescription)}
        values.update(changes, model=model)
        return cls(**values)

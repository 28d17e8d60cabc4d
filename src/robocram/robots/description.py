"""Typed robot descriptions: what CRAM's robot interface predicates say, as frozen values.

A :class:`RobotDescription` names a URDF and the parts of the robot plans talk about: base
and odom frames, torso, any number of named arms, cameras, a pan-tilt unit, and frames,
collision boxes or joint couplings to add to the model in code. ``load_description`` checks
it against the URDF and fills ``model``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Literal, get_args

from robocram.robots.errors import DescriptionError
from robocram.robots.findings import Finding
from robocram.robots.gripper import GripperDescription
from robocram.robots.model_additions import BoxSpec, FrameSpec, JointCoupling
from robocram.robots.robot_model import RobotModel


@dataclass(frozen=True)
class ArmDescription:
    """One kinematic chain that ends in a tool frame: an arm, or a neck that points a camera.

    Leave ``joints`` (and ``links``) empty to infer them from ``base_link`` to
    ``end_effector_link`` (the wrist). Joint values in ``parking`` and ``carrying`` are
    [rad] or [m].

    The tool frame follows one convention on every robot, so plans need not know the hand:
    its origin between the finger tips, x the approach direction (out of the palm), y the
    direction the fingers open in.

    The hand, defaults derived from the URDF at load when left empty:

    - ``gripper``: per joint, the open and closed positions, and the widest opening
      (:class:`~robocram.robots.gripper.GripperDescription`); by default from
      ``gripper_joints``, open at the upper limits and closed at the lower ones;
    - ``gripper_joints``: the joints that open and close it (the ``gripper``'s joints);
    - ``gripper_links``: the links those joints move (the fingers); gripping holds an
      object when they touch it;
    - ``hand_links``: every link that may touch the object being grasped (collision mode
      ``allow_hand``); by default the wrist and everything below it.
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
    gripper: GripperDescription | None = None
    # IK moves the base too; None: when the arm's reach envelope is a thin slice or small
    base_in_ik: bool | None = None


@dataclass(frozen=True)
class CameraDescription:
    """A camera: its optical frame (z forward, x right, y down) and where the torso can hold it.

    Heights left ``None`` are derived at load: the frame's height over the root link with
    the torso at its lower and upper limit (the neck parked).
    """

    frame: str
    minimal_height: float | None = None  # [m] over the floor
    maximal_height: float | None = None  # [m] over the floor
    horizontal_fov: float = field(kw_only=True)  # [rad]
    vertical_fov: float = field(kw_only=True)  # [rad]
    name: str = "camera"

    def height_range(self) -> tuple[float, float]:
        """``(minimal_height, maximal_height)`` [m]; set on every loaded description."""
        if self.minimal_height is None or self.maximal_height is None:
            raise DescriptionError(
                f"camera {self.frame!r} has no height range yet; load the description "
                "(load_description) to derive it from the torso's limits"
            )
        return self.minimal_height, self.maximal_height


@dataclass(frozen=True, kw_only=True)
class PanTiltDescription:
    """The joints of a pan-tilt head and the links they turn.

    Links left ``None`` are the joints' child links, filled in at load. Keyword-only, so a
    joint is never taken for a link by position.
    """

    pan_joint: str
    tilt_joint: str
    pan_link: str | None = None
    tilt_link: str | None = None

    def axes(self) -> tuple[tuple[str, str], tuple[str, str]]:
        """``((pan_joint, pan_link), (tilt_joint, tilt_link))``, pan first, of a loaded head."""
        if self.pan_link is None or self.tilt_link is None:
            raise DescriptionError(
                f"pan-tilt head {self.pan_joint!r}/{self.tilt_joint!r} has no links yet; "
                "load the description (load_description fills them in)"
            )
        return (self.pan_joint, self.pan_link), (self.tilt_joint, self.tilt_link)


BaseType = Literal["holonomic", "differential", "fixed"]
"""How the base moves: ``holonomic`` drives any way (omni wheels, casters), ``differential``
only forward, backward and turning (two driven wheels on one axle), ``fixed`` not at all."""
BASE_TYPES: tuple[str, ...] = get_args(BaseType)


DEFAULT_ALLOWED_CONTACTS: tuple[tuple[str, str], ...] = (("*", "floor"), ("gripper", "held"))
"""Which contacts are not collisions, as ``(robot links, other)`` rules. Robot links: ``*``
(any), ``gripper`` or ``hand`` (an arm's, with that arm's held object), ``base`` (links not
moved by any joint) or a link name; other: ``floor`` (objects of type floor), ``held`` (what
the arm holds), an object type or an object name."""


@dataclass(frozen=True)
class RobotDescription:
    """What plans need to know about one robot, beside its URDF.

    ``urdf`` is a file path or a ``package://pkg/path`` URI; ``package_paths`` are extra
    folders searched for ``package://`` URIs. ``model`` is ``None`` (or a model to use
    instead of reading ``urdf``) until ``load_description`` has parsed the URDF and
    checked every name against it, which gives a :class:`LoadedDescription`.
    ``stance`` holds joints no arm moves where the robot stands (a legged robot's hips:
    the world starts them there, the others at their value nearest 0).
    """

    name: str
    urdf: str | Path
    base_frame: str
    odom_frame: str = "odom"
    torso_link: str | None = None  # None: the torso joint's child link, set at load
    torso_joint: str | None = None
    arms: Mapping[str, ArmDescription] = field(default_factory=dict)
    cameras: tuple[CameraDescription, ...] = ()
    pan_tilt: PanTiltDescription | None = None
    neck_arm: str | None = None
    neck_parking: Mapping[str, float] = field(default_factory=dict)
    stance: Mapping[str, float] = field(default_factory=dict)  # legs: how it stands [rad | m]
    extra_frames: tuple[FrameSpec, ...] = ()
    extra_boxes: tuple[BoxSpec, ...] = ()
    coupled_joints: tuple[JointCoupling, ...] = ()  # joints one actuator moves (a telescope)
    package_paths: tuple[Path, ...] = ()
    flying: bool = False
    acceleration_limits: Mapping[str, float] = field(default_factory=dict)  # [rad/s^2 | m/s^2]
    holonomic: bool = True  # the base drives sideways; False: differential (kept for old files)
    base_type: BaseType | None = None  # None: from ``holonomic``; set, it wins over it
    allowed_contacts: tuple[tuple[str, str], ...] = DEFAULT_ALLOWED_CONTACTS
    # links whose mesh collides as its convex parts, not its hull (``robots/convex_parts.py``)
    decomposed_links: tuple[str, ...] = ()
    model: RobotModel | None = None
    source: str = field(default="", compare=False, kw_only=True)
    """Where the description was read: ``FILE.py:NAME`` (absolute) or ``module:NAME``, as
    :func:`~robocram.robots.description_source.description_from` takes it; empty for a
    built-in robot or one made in code. A trace keeps it to build the robot again."""

    def __post_init__(self) -> None:
        if self.base_type is not None and self.base_type not in BASE_TYPES:
            raise DescriptionError(
                f"base_type {self.base_type!r} of {self.name!r} is none of {BASE_TYPES}"
            )

    @property
    def drive(self) -> BaseType:
        """How the base moves: ``base_type``, else ``holonomic`` (True) or ``differential``."""
        if self.base_type is not None:
            return self.base_type
        return "holonomic" if self.holonomic else "differential"

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
    it never has to test ``model`` for None. ``findings`` are the checker's warnings
    (things plans need that were left out, doubtful frames).
    """

    model: RobotModel = field(kw_only=True)
    findings: tuple[Finding, ...] = field(default=(), kw_only=True, compare=False)

    @classmethod
    def checked(
        cls, desc: RobotDescription, model: RobotModel, **changes: object
    ) -> LoadedDescription:
        """``desc`` with ``model`` and ``changes`` applied (for ``load_description``)."""
        values = {f.name: getattr(desc, f.name) for f in fields(RobotDescription)}
        values.update(changes, model=model)
        return cls(**values)

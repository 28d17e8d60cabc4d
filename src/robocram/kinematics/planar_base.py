"""A robot's mobile base as three virtual joints before its root link, for IK.

An arm with fewer than six joints reaches only a lower-dimensional set of tool poses;
CRAM lets the HSR reach with its base too. Here the robot's model is extended by a
planar chain from a virtual origin to the URDF root link, with bounded travel. The origin
is the root link where the robot stands now, so a solution's base part is a
:class:`BaseMotion` relative to the current base pose: a drive, then the arm.

A holonomic base's chain is ``x`` (prismatic), ``y`` (prismatic), ``yaw`` (revolute). A
differential base cannot slide sideways, so its chain is the way it drives: ``turn``
(revolute, at most a quarter turn each way: farther, it backs), ``x`` (prismatic, the
drive along its heading) and ``yaw`` (revolute). Every base pose stays reachable (a pose
beside the robot by turning, driving and turning back), but no step of a solution moves
sideways, and a descent that starts without a turn never creeps sideways: at zero drive
the turn gives no lateral gradient. Which poses IK prefers is the starts' cost
(:mod:`~robocram.kinematics.planar_fit`): an offset sideways costs two turns.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

from robocram.kinematics.errors import KinematicsError
from robocram.robots import ArmDescription, RobotDescription, RobotModel
from robocram.robots.arm_slice import arm_slice
from robocram.robots.urdf_elements import Joint, JointType, Link
from robocram.tf import Pose
from robocram.tf import quaternion as quat

BASE_ORIGIN_LINK = "planar_base_origin"  # the virtual root: the base where it stands now
BASE_X_JOINT = "planar_base_x_joint"
BASE_Y_JOINT = "planar_base_y_joint"
BASE_YAW_JOINT = "planar_base_yaw_joint"
BASE_TURN_JOINT = "planar_base_turn_joint"  # a differential base's turn before it drives
BASE_JOINTS = (BASE_X_JOINT, BASE_Y_JOINT, BASE_YAW_JOINT)
DIFFERENTIAL_JOINTS = (BASE_TURN_JOINT, BASE_X_JOINT, BASE_YAW_JOINT)
VIRTUAL_JOINTS = frozenset(BASE_JOINTS + DIFFERENTIAL_JOINTS)
MAX_TURN = math.pi / 2  # [rad] a differential base turns at most this far before it drives
FULL_ARM_JOINTS = 6  # an unloaded arm with fewer joints (torso included) uses its base


@dataclass(frozen=True)
class PlanarBase:
    """How far IK may move the base from where it stands: x, y [m] and yaw [rad], each way.

    ``differential``: the base drives only along its heading (the chain turn, x, yaw);
    its drive goes at most the diagonal of the x-y travel, its last turn the yaw travel
    plus a quarter turn. Solvers set it from the description (:func:`for_robot`).
    """

    travel_x: float = 0.5  # [m]
    travel_y: float = 0.5  # [m]
    travel_yaw: float = math.pi  # [rad]
    differential: bool = False

    def __post_init__(self) -> None:
        for name in ("travel_x", "travel_y", "travel_yaw"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0.0):
                raise KinematicsError(
                    f"PlanarBase.{name} must be a finite travel > 0, got {value!r}; "
                    "leave the base out of IK (base=None) to keep it still"
                )
        if self.travel_yaw > math.pi:
            raise KinematicsError(
                f"PlanarBase.travel_yaw {self.travel_yaw!r} exceeds pi; a turn of pi each "
                "way already covers every heading"
            )

    @property
    def joints(self) -> tuple[str, str, str]:
        """The virtual joints of this base's chain, root first."""
        return DIFFERENTIAL_JOINTS if self.differential else BASE_JOINTS


@dataclass(frozen=True)
class BaseMotion:
    """A planar move of the base in its own frame: forward ``x``, left ``y`` [m], ``yaw`` [rad]."""

    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0

    def pose(self) -> Pose:
        """The moved base in the current base frame."""
        return Pose((self.x, self.y, 0.0), quat.from_euler(0.0, 0.0, self.yaw))

    def drive_steps(self) -> tuple[tuple[float, float, float], ...]:
        """The poses ``(x, y, yaw)`` of a drive that never slides: start, turned towards the
        goal (or away from it, to back: at most a quarter turn), there, turned to its yaw."""
        distance = self.distance
        if distance < 1e-9:
            return ((0.0, 0.0, 0.0), (0.0, 0.0, self.yaw))
        heading = math.atan2(self.y, self.x)
        if abs(heading) > MAX_TURN:  # back up: the turn before the drive is shorter
            heading -= math.copysign(math.pi, heading)
        return (
            (0.0, 0.0, 0.0),
            (0.0, 0.0, heading),
            (self.x, self.y, heading),
            (self.x, self.y, heading + math.remainder(self.yaw - heading, 2 * math.pi)),
        )

    @property
    def distance(self) -> float:
        """How far [m] the base's origin moves."""
        return math.hypot(self.x, self.y)


def split_base_motion(values: Mapping[str, float]) -> tuple[dict[str, float], BaseMotion | None]:
    """The robot's own joint values and the base motion among ``values`` (None if absent).

    Collision checks of a base-in-IK solve get the virtual joints with the others.
    """
    joints = {k: v for k, v in values.items() if k not in VIRTUAL_JOINTS}
    if BASE_TURN_JOINT in values:  # a differential base: turn, drive, turn
        turn = float(values[BASE_TURN_JOINT])
        ahead = float(values.get(BASE_X_JOINT, 0.0))
        yaw = turn + float(values.get(BASE_YAW_JOINT, 0.0))
        return joints, BaseMotion(ahead * math.cos(turn), ahead * math.sin(turn), yaw)
    if not any(k in values for k in BASE_JOINTS):
        return joints, None
    return joints, BaseMotion(*(float(values.get(k, 0.0)) for k in BASE_JOINTS))


def for_robot(description: RobotDescription, base: PlanarBase) -> PlanarBase:
    """``base`` for the description's drive: differential or not.

    Raises:
        KinematicsError: the description's base is fixed.
    """
    if description.drive == "fixed":
        raise KinematicsError(
            f"{description.name}'s base is fixed (base_type='fixed'): IK cannot move it; "
            "leave the base out (base=None, ArmDescription.base_in_ik=False)"
        )
    differential = description.drive == "differential"
    return base if base.differential == differential else replace(base, differential=differential)


def base_in_ik(description: RobotDescription, arm: str) -> bool:
    """Whether IK for ``arm`` reaches with the base too, as the description says.

    ``ArmDescription.base_in_ik`` decides when set. By default an arm (not the neck) of a
    base that moves uses it when its reach envelope is a thin slice or small
    (:func:`~robocram.robots.arm_slice.arm_slice`: Stretch's, the HSR's, the SO-101's),
    not by its number of joints: Stretch's five move in one plane. An unloaded
    description falls back to the count: fewer than six joints, the torso's counted.
    """
    spec: ArmDescription | None = description.arms.get(arm)
    if spec is None or arm == description.neck_arm and spec.base_in_ik is None:
        return False
    if spec.base_in_ik is not None:
        return spec.base_in_ik
    if description.drive == "fixed":
        return False
    if description.model is not None and spec.joints:
        return arm_slice(description.model, spec).needs_base
    joints = set(spec.joints)
    if description.torso_joint is not None:
        joints.add(description.torso_joint)
    return 0 < len(joints) < FULL_ARM_JOINTS


def with_planar_base(model: RobotModel, base: PlanarBase) -> RobotModel:
    """``model`` below the virtual planar joints of ``base`` (a new model each call:
    :meth:`~robocram.kinematics.KinematicsCache.planar_model` keeps one)."""
    first, second = ("planar_base_turn", "planar_base_x") if base.differential else (
        "planar_base_x", "planar_base_y",
    )  # fmt: skip
    clash = [n for n in (BASE_ORIGIN_LINK, first, second) if n in model.links]
    clash += [n for n in VIRTUAL_JOINTS if n in model.joints]
    if clash:
        raise KinematicsError(
            f"{model.source} already has {clash}, the names of the virtual base joints; "
            "rename them in the URDF or set ArmDescription.base_in_ik=False"
        )
    chain = _differential(base, first, second, model.root_link) if base.differential else (
        _virtual(BASE_X_JOINT, "prismatic", (BASE_ORIGIN_LINK, first), (1, 0, 0), base.travel_x),
        _virtual(BASE_Y_JOINT, "prismatic", (first, second), (0, 1, 0), base.travel_y),
        _virtual(BASE_YAW_JOINT, "revolute", (second, model.root_link), (0, 0, 1), base.travel_yaw),
    )  # fmt: skip
    links = {name: Link(name) for name in (BASE_ORIGIN_LINK, first, second)}
    joints = {j.name: j for j in chain}
    return RobotModel(
        model.name, {**links, **model.links}, {**joints, **model.joints}, model.source
    )


def _differential(base: PlanarBase, first: str, second: str, root: str) -> tuple[Joint, ...]:
    """The chain turn, drive, turn of a differential base (see :class:`PlanarBase`)."""
    drive = math.hypot(base.travel_x, base.travel_y)
    last = base.travel_yaw + MAX_TURN
    return (
        _virtual(BASE_TURN_JOINT, "revolute", (BASE_ORIGIN_LINK, first), (0, 0, 1), MAX_TURN),
        _virtual(BASE_X_JOINT, "prismatic", (first, second), (1, 0, 0), drive),
        _virtual(BASE_YAW_JOINT, "revolute", (second, root), (0, 0, 1), last),
    )


def _virtual(
    name: str,
    kind: JointType,
    parent_child: tuple[str, str],
    axis: tuple[float, float, float],
    travel: float,
) -> Joint:
    """One virtual base joint moving ``travel`` [m | rad] each way along or about ``axis``."""
    parent, child = parent_child
    return Joint(name, kind, parent, child, axis=axis, lower=-travel, upper=travel,
                 velocity=1.0, effort=1.0)  # fmt: skip

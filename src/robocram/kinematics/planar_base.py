"""A robot's mobile base as three virtual joints before its root link, for IK.

An arm with fewer than six joints reaches only a lower-dimensional set of tool poses;
CRAM lets the HSR reach with its base too. Here the robot's model is extended by a
planar chain ``x`` (prismatic), ``y`` (prismatic), ``yaw`` (revolute), in that order,
from a virtual origin to the URDF root link, with bounded travel. The origin is the
root link where the robot stands now, so a solution's base part is a
:class:`BaseMotion` relative to the current base pose: a drive, then the arm.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from robocram.kinematics.errors import KinematicsError
from robocram.robots import ArmDescription, RobotDescription, RobotModel
from robocram.robots.urdf_elements import Joint, JointType, Link
from robocram.tf import Pose
from robocram.tf import quaternion as quat

BASE_ORIGIN_LINK = "planar_base_origin"  # the virtual root: the base where it stands now
BASE_X_JOINT = "planar_base_x_joint"
BASE_Y_JOINT = "planar_base_y_joint"
BASE_YAW_JOINT = "planar_base_yaw_joint"
BASE_JOINTS = (BASE_X_JOINT, BASE_Y_JOINT, BASE_YAW_JOINT)
FULL_ARM_JOINTS = 6  # an arm with fewer joints (torso included) reaches with its base too


@dataclass(frozen=True)
class PlanarBase:
    """How far IK may move the base from where it stands: x, y [m] and yaw [rad], each way."""

    travel_x: float = 0.5  # [m]
    travel_y: float = 0.5  # [m]
    travel_yaw: float = math.pi  # [rad]

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


@dataclass(frozen=True)
class BaseMotion:
    """A planar move of the base in its own frame: forward ``x``, left ``y`` [m], ``yaw`` [rad]."""

    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0

    def pose(self) -> Pose:
        """The moved base in the current base frame."""
        return Pose((self.x, self.y, 0.0), quat.from_euler(0.0, 0.0, self.yaw))

    @property
    def distance(self) -> float:
        """How far [m] the base's origin moves."""
        return math.hypot(self.x, self.y)


def split_base_motion(values: Mapping[str, float]) -> tuple[dict[str, float], BaseMotion | None]:
    """The robot's own joint values and the base motion among ``values`` (None if absent).

    Collision checks of a base-in-IK solve get the virtual joints with the others.
    """
    joints = {k: v for k, v in values.items() if k not in BASE_JOINTS}
    if not any(k in values for k in BASE_JOINTS):
        return joints, None
    return joints, BaseMotion(*(float(values.get(k, 0.0)) for k in BASE_JOINTS))


def base_in_ik(description: RobotDescription, arm: str) -> bool:
    """Whether IK for ``arm`` reaches with the base too, as the description says.

    ``ArmDescription.base_in_ik`` decides when set; by default an arm (not the neck) with
    fewer than six joints, the torso joint counted, uses the base.
    """
    spec: ArmDescription | None = description.arms.get(arm)
    if spec is None or arm == description.neck_arm and spec.base_in_ik is None:
        return False
    if spec.base_in_ik is not None:
        return spec.base_in_ik
    joints = set(spec.joints)
    if description.torso_joint is not None:
        joints.add(description.torso_joint)
    if description.model is not None:
        joints = {
            j
            for j in joints
            if j in description.model.joints and description.model.joints[j].mimic is None
        }
    return 0 < len(joints) < FULL_ARM_JOINTS


def with_planar_base(model: RobotModel, base: PlanarBase) -> RobotModel:
    """``model`` below the virtual planar joints of ``base`` (a new model each call:
    :meth:`~robocram.kinematics.KinematicsCache.planar_model` keeps one)."""
    clash = [n for n in (BASE_ORIGIN_LINK, "planar_base_x", "planar_base_y") if n in model.links]
    clash += [n for n in BASE_JOINTS if n in model.joints]
    if clash:
        raise KinematicsError(
            f"{model.source} already has {clash}, the names of the virtual base joints; "
            "rename them in the URDF or set ArmDescription.base_in_ik=False"
        )
    x_link, y_link = "planar_base_x", "planar_base_y"
    chain = (
        _virtual(BASE_X_JOINT, "prismatic", (BASE_ORIGIN_LINK, x_link), (1, 0, 0), base.travel_x),
        _virtual(BASE_Y_JOINT, "prismatic", (x_link, y_link), (0, 1, 0), base.travel_y),
        _virtual(BASE_YAW_JOINT, "revolute", (y_link, model.root_link), (0, 0, 1), base.travel_yaw),
    )
    links = {name: Link(name) for name in (BASE_ORIGIN_LINK, x_link, y_link)}
    joints = {j.name: j for j in chain}
    return RobotModel(
        model.name, {**links, **model.links}, {**joints, **model.joints}, model.source
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

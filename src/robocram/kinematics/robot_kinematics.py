"""The pinocchio model of a whole robot, with the joint facts its URDF states.

Built once per :class:`~robocram.robots.RobotModel` from ``model.to_urdf()`` (so frames
and boxes added in code are there) and kept with the model (``RobotModel.derived``).
Pinocchio reads mimic joints as free joints; the coupling is kept here and applied by the
IK and by :meth:`configuration`.
Poses are expressed in the URDF root link (pinocchio's universe frame coincides with it).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.errors import KinematicsUsageError, TargetFrameError, UnknownNameError
from robocram.robots import RobotModel
from robocram.robots.lazy_library import LazyLibrary
from robocram.robots.mimic import mimic_followers
from robocram.tf import Pose, PoseStamped

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")


@dataclass(frozen=True)
class JointInfo:
    """What IK needs of one movable joint: where its value sits in pinocchio's vectors."""

    name: str
    pin_id: int  # pinocchio joint index
    idx_q: int  # first configuration index; continuous joints use (cos, sin) at idx_q
    idx_v: int  # velocity index (one per joint)
    continuous: bool
    lower: float  # [rad | m]; -inf for continuous joints
    upper: float  # [rad | m]; inf for continuous joints


def se3_to_pose(m: pin.SE3) -> Pose:
    """Pose of a pinocchio SE3."""
    q = pin.Quaternion(m.rotation)
    return Pose(tuple(m.translation), (q.x, q.y, q.z, q.w))


def pose_to_se3(pose: Pose) -> pin.SE3:
    """Pinocchio SE3 of a pose (one pinocchio call: a third of the three it replaces, the
    same rotation matrix bit for bit; a tool line asks for one per 2 cm)."""
    return pin.XYZQUATToSE3(np.array((*pose.position, *pose.orientation)))


class RobotKinematics:
    """A robot's full pinocchio model, joint table and mimic couplings."""

    def __init__(self, robot_model: RobotModel) -> None:
        self.robot_model = robot_model
        self.name = robot_model.name
        self.root_link = robot_model.root_link
        self.model: pin.Model = pin.buildModelFromXML(robot_model.to_urdf())
        self.data: pin.Data = self.model.createData()
        self.joints: dict[str, JointInfo] = {}
        for pin_id in range(1, self.model.njoints):
            self._add_joint(pin_id)

    def _add_joint(self, pin_id: int) -> None:
        name = self.model.names[pin_id]
        joint = self.robot_model.joints[name]
        jm = self.model.joints[pin_id]
        continuous = jm.nq == 2
        lower = -math.inf if continuous else float(joint.lower if joint.lower is not None else 0)
        upper = math.inf if continuous else float(joint.upper if joint.upper is not None else 0)
        self.joints[name] = JointInfo(name, pin_id, jm.idx_q, jm.idx_v, continuous, lower, upper)

    def joint(self, name: str) -> JointInfo:
        """The movable joint ``name``; raise with close names if there is none."""
        info = self.joints.get(name)
        if info is None:
            raise UnknownNameError("movable joint", name, self.robot_model.source, self.joints)
        return info

    def frame_id(self, frame: str) -> int:
        """Pinocchio frame index of a link or frame of the robot.

        A URDF may name a joint as one of its links (the Z1's ``gripperStator``): pinocchio
        then has two frames of that name, and the link's (a body frame) is meant.
        """
        if not self.model.existFrame(frame):
            names = [f.name for f in self.model.frames if f.name != "universe"]
            raise UnknownNameError("frame", frame, self.robot_model.source, names)
        if self.model.existFrame(frame, pin.FrameType.BODY):
            return int(self.model.getFrameId(frame, pin.FrameType.BODY))
        return int(self.model.getFrameId(frame))

    def default_value(self, name: str) -> float:
        """The value nearest 0 within the joint's limits [rad | m]."""
        info = self.joints[name]
        return min(max(0.0, info.lower), info.upper)

    def configuration(self, joint_positions: Mapping[str, float]) -> NDArray[np.float64]:
        """Pinocchio configuration of named joint values; others at their defaults.

        Mimic followers not given follow their masters.
        """
        for name in joint_positions:
            self.joint(name)
        values = mimic_followers(self.robot_model, joint_positions)
        q = pin.neutral(self.model)
        for name, info in self.joints.items():
            value = float(values[name]) if name in values else self.default_value(name)
            if info.continuous:
                q[info.idx_q] = math.cos(value)
                q[info.idx_q + 1] = math.sin(value)
            else:
                q[info.idx_q] = value
        return q

    def put(self, q: NDArray[np.float64], name: str, value: float) -> None:
        """Write joint ``name``'s ``value`` [rad | m] into the configuration ``q``."""
        info = self.joints[name]
        if info.continuous:
            q[info.idx_q], q[info.idx_q + 1] = math.cos(value), math.sin(value)
        else:
            q[info.idx_q] = value

    def frame_matrices(
        self, q: NDArray[np.float64], frames: Sequence[int]
    ) -> list[NDArray[np.float64]]:
        """The 4 x 4 placements in the root link of the frames (ids) at configuration ``q``:
        one forward pass for several frames."""
        pin.forwardKinematics(self.model, self.data, q)
        return [pin.updateFramePlacement(self.model, self.data, f).homogeneous for f in frames]

    def frame_pose(self, frame: str, joint_positions: Mapping[str, float]) -> Pose:
        """Pose of ``frame`` in the root link for the given joint values."""
        fid = self.frame_id(frame)
        pin.framesForwardKinematics(self.model, self.data, self.configuration(joint_positions))
        return se3_to_pose(self.data.oMf[fid])

    def pose_in_root(
        self, target: Pose | PoseStamped, joint_positions: Mapping[str, float]
    ) -> Pose:
        """``target`` in the root link: a Pose is taken as given there; a PoseStamped in
        another link or frame of the robot is placed by FK of ``joint_positions``."""
        if isinstance(target, Pose):
            return target
        if not isinstance(target, PoseStamped):
            raise KinematicsUsageError(f"a target must be a Pose or a PoseStamped, got {target!r}")
        if target.frame_id == self.root_link:
            return target.pose
        if not self.model.existFrame(target.frame_id):
            raise TargetFrameError(target.frame_id, self.name, self.root_link)
        return self.frame_pose(target.frame_id, joint_positions) * target.pose


def robot_kinematics(robot_model: RobotModel) -> RobotKinematics:
    """The kinematics of ``robot_model``, built once and kept with the model."""
    return robot_model.derived(RobotKinematics)

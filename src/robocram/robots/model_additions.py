"""Frames, collision boxes and joint couplings a description adds to its model in code.

The URDF text is never edited: :meth:`RobotModel.with_frame`, ``with_box`` and
``with_coupling`` make a new model with the addition, and a :class:`RobotDescription` lists
them in ``extra_frames``, ``extra_boxes`` and ``coupled_joints``.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Pose


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
class JointCoupling:
    """Joints that move as one actuator: each follower = multiplier * actuator + offset.

    Stretch's telescope is four prismatic joints in the URDF and one motor on the robot:
    ``JointCoupling("joint_arm_l3", ("joint_arm_l2", "joint_arm_l1", "joint_arm_l0"))``.
    At load the followers become ``<mimic>`` joints of the actuator, so IK, the projected
    robot and trajectories move the actuator and set the followers with it.
    """

    actuator: str
    followers: tuple[str, ...]
    multiplier: float = 1.0
    offset: float = 0.0  # [m | rad]

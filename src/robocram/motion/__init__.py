"""Motions a real robot can execute: collision-checked paths and timed trajectories.

A motion's goal (joint values from IK, a base pose) becomes a path that is checked densely
against the world, planned around obstacles when the straight way is blocked (OMPL), and
timed under the robot's limits; projection follows the trajectory and ROS sends it whole.
See docs/motion.md.
"""

from robocram.motion.arm_motion import ArmMotion, MotionSettings, plan_arm_motion, plan_tool_line
from robocram.motion.base_path import BasePath, plan_base_path
from robocram.motion.carried_joint import CarriedJoint
from robocram.motion.collision_scene import CollisionScene
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.errors import MotionError
from robocram.motion.joint_limits import JointLimits, joint_limits
from robocram.motion.joint_trajectory import (
    BASE_JOINTS,
    BODY_JOINTS,
    JointTrajectory,
    TrajectoryPoint,
    still,
)
from robocram.motion.time_parameterization import time_parameterize
from robocram.motion.trajectory_log import report_executed, trajectory_listener

__all__ = [
    "ArmMotion",
    "BASE_JOINTS",
    "BODY_JOINTS",
    "BasePath",
    "CollisionScene",
    "CarriedJoint",
    "ContactAllowance",
    "JointLimits",
    "JointTrajectory",
    "MotionError",
    "MotionSettings",
    "TrajectoryPoint",
    "joint_limits",
    "plan_arm_motion",
    "plan_base_path",
    "plan_tool_line",
    "report_executed",
    "still",
    "time_parameterize",
    "trajectory_listener",
]

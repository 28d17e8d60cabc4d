"""Inverse and forward kinematics of robot descriptions on pinocchio, mimic-aware."""

from robocram.kinematics.arm_selection import arm_joints
from robocram.kinematics.base_ik_solver import BaseIKSolver
from robocram.kinematics.descent import IKSettings
from robocram.kinematics.described_robot import DescribedRobot, RobotRef
from robocram.kinematics.errors import (
    KinematicsArgumentError,
    KinematicsError,
    KinematicsUsageError,
    TargetFrameError,
    UnknownNameError,
)
from robocram.kinematics.ik_options import IKOptions
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import CollisionCheck, IKSolver
from robocram.kinematics.kinematics_cache import KinematicsCache
from robocram.kinematics.planar_base import BaseMotion, PlanarBase, base_in_ik, split_base_motion
from robocram.kinematics.reach import ReachBound
from robocram.kinematics.solve_ik import forward_kinematics, reachable, solve_ik
from robocram.kinematics.track_ik import track_ik

__all__ = [
    "BaseIKSolver",
    "BaseMotion",
    "CollisionCheck",
    "DescribedRobot",
    "IKOptions",
    "IKResult",
    "IKSettings",
    "IKSolver",
    "KinematicsArgumentError",
    "KinematicsCache",
    "KinematicsError",
    "KinematicsUsageError",
    "PlanarBase",
    "ReachBound",
    "RobotRef",
    "TargetFrameError",
    "UnknownNameError",
    "arm_joints",
    "base_in_ik",
    "forward_kinematics",
    "reachable",
    "solve_ik",
    "split_base_motion",
    "track_ik",
]

"""Inverse and forward kinematics of robot descriptions on pinocchio, mimic-aware."""

from robocram.kinematics.arm_selection import arm_joints
from robocram.kinematics.errors import KinematicsError, TargetFrameError, UnknownNameError
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import CollisionCheck, IKSettings, IKSolver
from robocram.kinematics.solve_ik import forward_kinematics, solve_ik

__all__ = [
    "CollisionCheck",
    "IKResult",
    "IKSettings",
    "IKSolver",
    "KinematicsError",
    "TargetFrameError",
    "UnknownNameError",
    "arm_joints",
    "forward_kinematics",
    "solve_ik",
]

"""Inverse and forward kinematics of robot descriptions on pinocchio, mimic-aware."""

from robocram.kinematics.arm_selection import arm_joints
from robocram.kinematics.descent import IKSettings
from robocram.kinematics.errors import KinematicsError, TargetFrameError, UnknownNameError
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import CollisionCheck, IKSolver
from robocram.kinematics.reach import ReachBound
from robocram.kinematics.solve_ik import forward_kinematics, reachable, solve_ik

__all__ = [
    "CollisionCheck",
    "IKResult",
    "IKSettings",
    "IKSolver",
    "KinematicsError",
    "ReachBound",
    "TargetFrameError",
    "UnknownNameError",
    "arm_joints",
    "forward_kinematics",
    "reachable",
    "solve_ik",
]

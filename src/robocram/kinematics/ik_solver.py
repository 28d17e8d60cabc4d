"""Damped least-squares IK on pinocchio, within joint limits, with random restarts.

Each step solves ``(J^T J + (e^T e + damping) I) dx = J^T e`` (Levenberg-Marquardt with
the error-dependent damping of Sugihara 2011), ``e = log6(current^-1 * target)`` in the tool
frame and ``J`` the matching Jacobian (``Jlog6 * frame Jacobian * A``, see
:mod:`~robocram.kinematics.arm_chain`), then clamps ``x`` into the joint limits. A descent
that stops improving restarts from a random configuration within limits.

Budgets are counted, never timed: ``max_restarts`` descents of at most ``max_iterations``
steps each, so the same query and random seed give bit-identical answers on an idle and
on a loaded machine.
"""

from __future__ import annotations

import math
import time
import weakref
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.kinematics.arm_selection import arm_description, arm_joints, loaded
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.robot_kinematics import pose_to_se3, robot_kinematics
from robocram.robots import RobotDescription, RobotModel
from robocram.tf import Pose, PoseStamped

CollisionCheck = Callable[[dict[str, float]], bool]
"""Called with a candidate's joint values; returns True when that configuration collides."""


@dataclass(frozen=True)
class IKSettings:
    """Tolerances and budgets of one IK query."""

    position_tolerance: float = 1e-3  # [m]
    orientation_tolerance: float = 1e-2  # [rad]
    max_restarts: int = 100  # descents after the first one
    max_iterations: int = 60  # steps per descent
    stall_iterations: int = 8  # steps without 0.1 % improvement that end a descent
    damping: float = 1e-4


@dataclass
class _Best:
    """The configuration closest to the target so far."""

    x: FloatArray
    cost: float = math.inf
    position_error: float = math.inf
    orientation_error: float = math.inf


_SOLVERS: weakref.WeakKeyDictionary[RobotModel, dict[tuple[str, bool, str | None], IKSolver]] = (
    weakref.WeakKeyDictionary()
)


class IKSolver:
    """IK for the tool frame of one arm of a description (optionally moving the torso).

    Build it once and query it many times; :meth:`cached` shares solvers between callers.
    """

    def __init__(
        self,
        description: RobotDescription | str,
        arm: str,
        use_torso: bool = False,
        frame: str | None = None,
    ) -> None:
        desc, model = loaded(description)
        self.description = desc
        self.arm = arm
        self.use_torso = use_torso
        joints = arm_joints(desc, arm, use_torso)
        self.frame = frame or arm_description(desc, arm).tool_frame
        self.chain = ArmChain(robot_kinematics(model), joints, self.frame)
        n = len(self.chain.variables)
        self._eye = np.eye(n)
        finite = np.isfinite(self.chain.lower) & np.isfinite(self.chain.upper)
        self._finite = finite
        middle = (
            np.where(finite, self.chain.lower, 0.0) + np.where(finite, self.chain.upper, 0.0)
        ) / 2
        self._middle = middle

    @classmethod
    def cached(
        cls,
        description: RobotDescription | str,
        arm: str,
        use_torso: bool = False,
        frame: str | None = None,
    ) -> IKSolver:
        """The solver for these arguments, built on first use and kept with the model."""
        desc, model = loaded(description)
        per_model = _SOLVERS.setdefault(model, {})
        key = (arm, use_torso, frame)
        solver = per_model.get(key)
        if solver is None or solver.description.arms != desc.arms:
            solver = cls(desc, arm, use_torso, frame)
            per_model[key] = solver
        return solver

    @property
    def variables(self) -> tuple[str, ...]:
        """The joints IK sets (mimic joints replaced by their masters)."""
        return self.chain.variables

    def start(self, seed: Mapping[str, float]) -> FloatArray:
        """Start configuration: the seed's values, else mid-range (0 for continuous joints)."""
        x = np.array(
            [seed.get(v, self._middle[k]) for k, v in enumerate(self.chain.variables)], float
        )
        return np.clip(x, self.chain.lower, self.chain.upper)

    def _random(self, rng: np.random.Generator, reference: FloatArray) -> FloatArray:
        lo = np.where(self._finite, self.chain.lower, reference - math.pi)
        hi = np.where(self._finite, self.chain.upper, reference + math.pi)
        return rng.uniform(lo, hi)

    def solve(
        self,
        target: Pose | PoseStamped,
        seed: Mapping[str, float] | None = None,
        settings: IKSettings | None = None,
        collision_check: CollisionCheck | None = None,
        rng: np.random.Generator | None = None,
    ) -> IKResult:
        """Joint values putting the tip frame at ``target`` (see :func:`solve_ik`)."""
        t0 = time.perf_counter()
        s = settings or IKSettings()
        seed = seed or {}
        rng = rng or np.random.default_rng(0)
        target_se3 = pose_to_se3(self.chain.kin.pose_in_root(target, seed))
        b = self.chain.offsets(seed)
        reference = self.start(seed)
        x, best = reference.copy(), _Best(reference.copy())
        iterations = restarts = rejected = 0
        while True:
            converged, x, used = self._descend(x, target_se3, b, s, best)
            iterations += used
            if converged:
                values = self.chain.joint_positions(self.chain.wrap_continuous(x, reference))
                if collision_check is None or not collision_check(values):
                    return self._result(True, values, best, iterations, restarts, rejected, t0)
                rejected += 1
            if restarts >= s.max_restarts:
                values = self.chain.joint_positions(self.chain.wrap_continuous(best.x, reference))
                return self._result(False, values, best, iterations, restarts, rejected, t0)
            restarts += 1
            x = self._random(rng, reference)

    def _descend(
        self, x: FloatArray, target: pin.SE3, b: FloatArray, s: IKSettings, best: _Best
    ) -> tuple[bool, FloatArray, int]:
        chain, model, data, fid = self.chain, self.chain.model, self.chain.data, self.chain.frame_id
        lower, upper, eye = chain.lower, chain.upper, self._eye
        last_cost, stall = math.inf, 0
        for it in range(1, s.max_iterations + 1):
            pin.computeJointJacobians(model, data, chain.configuration(x, b))
            current = pin.updateFramePlacement(model, data, fid)
            delta = current.actInv(target)
            err = pin.log6(delta).vector
            pos_err = float(np.linalg.norm(target.translation - current.translation))
            rot_err = float(np.linalg.norm(err[3:]))
            cost = float(err @ err)
            if cost < best.cost:
                best.x, best.cost = x, cost
                best.position_error, best.orientation_error = pos_err, rot_err
            if pos_err < s.position_tolerance and rot_err < s.orientation_tolerance:
                best.x, best.position_error, best.orientation_error = x, pos_err, rot_err
                return True, x, it
            stall = stall + 1 if cost > last_cost * 0.999 else 0
            if stall >= s.stall_iterations:
                return False, x, it
            last_cost = min(last_cost, cost)
            jac = pin.Jlog6(delta) @ pin.getFrameJacobian(model, data, fid, pin.LOCAL)
            if not chain.identity_map:
                jac = jac @ chain.a
            hessian = jac.T @ jac + (cost + s.damping) * eye
            x = np.clip(x + np.linalg.solve(hessian, jac.T @ err), lower, upper)
        return False, x, s.max_iterations

    def _result(
        self,
        success: bool,
        values: dict[str, float],
        best: _Best,
        iterations: int,
        restarts: int,
        rejected: int,
        t0: float,
    ) -> IKResult:
        return IKResult(
            success=success,
            joint_positions=values,
            position_error=best.position_error,
            orientation_error=best.orientation_error,
            iterations=iterations,
            restarts=restarts,
            elapsed=time.perf_counter() - t0,
            rejected_in_collision=rejected,
        )

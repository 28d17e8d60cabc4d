"""One damped least-squares descent towards a tool target, within joint limits.

Each step solves ``(J^T J + (w e^T e + damping) I) dx = J^T e`` (Levenberg-Marquardt with
the error-dependent damping of Sugihara 2011), ``e = log6(current^-1 * target)`` in the tool
frame and ``J`` the matching Jacobian (``Jlog6 * frame Jacobian * A``, see
:mod:`~robocram.kinematics.arm_chain`). A step that would leave the limits is not just
clamped, which stalls the descent against the limit: the variables it pushes out are held
at their limit and the step is solved again for the others, which can still move the tool
(the active-set idea of bounded least squares).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")


def _lapack_solve() -> Callable[[FloatArray, FloatArray], FloatArray]:
    """LAPACK's gesv as ``np.linalg.solve`` calls it, without its checks (4 of its 5 us;
    the damping keeps the matrix regular); a numpy without that private module gets the
    public call, which gives the same bits."""
    try:
        from numpy.linalg._umath_linalg import solve1
    except ImportError:
        return _public_solve
    return solve1


def _public_solve(a: FloatArray, b: FloatArray) -> FloatArray:
    return np.asarray(np.linalg.solve(a, b), dtype=np.float64)


_gesv = _lapack_solve()


@dataclass(frozen=True)
class IKSettings:
    """Tolerances and budgets of one IK query; every budget is a count, none a time."""

    position_tolerance: float = 1e-3  # [m]
    orientation_tolerance: float = 1e-2  # [rad]
    max_restarts: int = 100  # descents after the first one
    max_iterations: int = 60  # steps per descent
    stall_iterations: int = 4  # steps without 0.1 % improvement that end a descent
    damping: float = 1e-4  # constant part of the damping
    error_damping: float = 0.01  # weight of e^T e in the damping
    table_starts: int = 4  # descents from the nearest table samples before random ones
    fruitless_descents: int = 8  # stalls in a row without a 1 % lower minimum end the search


@dataclass
class Best:
    """The configuration closest to the target so far, and its errors."""

    x: FloatArray
    cost: float = math.inf
    position_error: float = math.inf  # [m]
    orientation_error: float = math.inf  # [rad]


class Descent(NamedTuple):
    """How a descent ended: converged, stalled in a minimum, or out of steps."""

    converged: bool
    x: FloatArray
    iterations: int
    stalled: bool
    minimum: float  # lowest e^T e of this descent


def _held_step(
    chain: ArmChain,
    x: FloatArray,
    jac: FloatArray,
    err: FloatArray,
    damping: float,
    moved: FloatArray,
    clamped: FloatArray,
) -> FloatArray:
    """The damped step ``moved`` from ``x``, which leaves the limits (``clamped`` is it
    clamped), with the variables it pushes past a limit held there.

    Holding some variables can push others out, so the step is solved again until none
    leaves its limits (at most once per variable).
    """
    lower, upper = chain.lower, chain.upper
    out = clamped != moved
    if True not in out.tolist():  # ``out.any()`` without its two Python layers
        return moved
    free = ~out
    rest = err
    for k in range(x.size - 1):
        rest = rest - jac[:, out] @ (clamped[out] - x[out])
        moved[out] = clamped[out]
        x = np.where(out, clamped, x)
        if k:
            free &= ~out
        if True not in free.tolist():
            break
        moved[free] = x[free] + _damped_solve(jac[:, free], rest, damping)
        clamped = np.minimum(np.maximum(moved, lower), upper)
        if clamped.tolist() == moved.tolist():  # as in :func:`descend`
            return moved
        out = clamped != moved
    return clamped


def _damped_solve(jac: FloatArray, err: FloatArray, damping: float) -> FloatArray:
    """``(J^T J + damping I)^-1 J^T e``.

    LAPACK's ``gesv``, as ``np.linalg.solve`` calls it, without that function's checks
    and error-state set-up: they cost four of its five microseconds, and the damped
    matrix is positive definite, never singular. ``dot`` calls the same BLAS routines as
    ``@`` (``syrk`` for ``J^T J``, ``gemv``), so gives the same bits, at half the call's cost;
    so does adding to a strided view of the diagonal rather than through ``flat``.
    """
    jac_t = jac.T
    hessian = jac_t.dot(jac)
    hessian.ravel()[:: hessian.shape[0] + 1] += damping
    return _gesv(hessian, jac_t.dot(err))


def descend(
    chain: ArmChain, x: FloatArray, target: pin.SE3, b: FloatArray, s: IKSettings, best: Best
) -> Descent:
    """Descend from ``x`` until the tool is within tolerance, stalls, or runs out of steps."""
    model, data, fid = chain.model, chain.data, chain.frame_id
    configuration, in_variables = chain.configuration, chain.variable_jacobian
    lower, upper, low, high = chain.lower, chain.upper, np.maximum, np.minimum
    jacobians, place, log6 = pin.computeJointJacobians, pin.updateFramePlacement, pin.log6
    jlog6, frame_jacobian, local = pin.Jlog6, pin.getFrameJacobian, pin.LOCAL
    position_tol2, orientation_tol2 = s.position_tolerance**2, s.orientation_tolerance**2
    error_damping, damping = s.error_damping, s.damping
    last, minimum, stall = math.inf, math.inf, 0
    for it in range(1, s.max_iterations + 1):
        jacobians(model, data, configuration(x, b))
        delta = place(model, data, fid).actInv(target)
        err = log6(delta).vector
        cost = float(err.dot(err))  # as ``@``: the same BLAS dot, at half the call's cost
        shift, turn = delta.translation, err[3:]
        position2, orientation2 = float(shift.dot(shift)), float(turn.dot(turn))
        if cost < minimum:
            minimum = cost
        done = position2 < position_tol2 and orientation2 < orientation_tol2
        if cost < best.cost or done:
            best.x, best.cost = x, cost
            best.position_error, best.orientation_error = (
                math.sqrt(position2),
                math.sqrt(orientation2),
            )
        if done:
            return Descent(True, x, it, False, minimum)
        stall = stall + 1 if cost > last * 0.999 else 0
        if stall >= s.stall_iterations:
            return Descent(False, x, it, True, minimum)
        if cost < last:
            last = cost
        jac = in_variables(jlog6(delta).dot(frame_jacobian(model, data, fid, local)))
        step_damping = cost * error_damping + damping
        moved = x + _damped_solve(jac, err, step_damping)
        clamped = high(low(moved, lower), upper)
        # nearly every step stays within the limits; comparing the lists (a quarter of the
        # cost of ``(clamped != moved).any()``) is that test: float ==, NaN unequal
        if clamped.tolist() == moved.tolist():
            x = moved
        else:
            x = _held_step(chain, x, jac, err, step_damping, moved, clamped)
    return Descent(False, x, s.max_iterations, False, minimum)

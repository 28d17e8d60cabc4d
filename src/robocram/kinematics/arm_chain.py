"""The part of a robot that moves a tool frame: a reduced pinocchio model plus couplings.

IK works on *variables*: the arm's joints (and the torso joint when it may move), with a
mimic joint replaced by its master. Every movable joint on the path from the root to the
tool frame is then a linear function of the variables, ``value = A @ x + b``: a variable
(row of the identity), a mimic follower (``multiplier``, ``offset``) or a joint held at its
seed value (row of zeros, ``b`` = seed). The Jacobian with respect to the variables is the
pinocchio Jacobian times ``A``, which is how mimic columns get combined into their master.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import RobotKinematics
from robocram.robots.lazy_library import LazyLibrary
from robocram.robots.mimic import mimic_followers

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

FloatArray = NDArray[np.float64]


LOCKED_SUFFIX = "#locked"  # appended to a locked joint named like a link, in the reduction


def _renamed_locked(model: pin.Model, lock: list[int]) -> pin.Model:
    """``model``, or a copy whose locked joints named like one of its links are renamed.

    A locked joint becomes a fixed frame of its name, which pinocchio's reduction looks up
    by name: a joint named like a link (the SO-100's ``gripper`` joint and link) matches
    two frames there and the reduction fails. The locked joints leave the reduced model,
    so their names are never looked up in it.
    """
    links = {f.name for f in model.frames if f.type == pin.FrameType.BODY}
    clashing = {model.names[j] for j in lock if model.names[j] in links}
    if not clashing:
        return model
    copy = pin.Model(model)
    for j in lock:
        if copy.names[j] in clashing:
            copy.names[j] = copy.names[j] + LOCKED_SUFFIX
    for i, frame in enumerate(copy.frames):
        if frame.type == pin.FrameType.JOINT and frame.name in clashing:
            frame.name = frame.name + LOCKED_SUFFIX
            copy.frames[i] = frame
    return copy


class ArmChain:
    """Variables, limits and the reduced model for moving ``tip_frame`` with ``joints``."""

    def __init__(self, kin: RobotKinematics, joints: Iterable[str], tip_frame: str) -> None:
        self.kin = kin
        self.tip_frame = tip_frame
        tip_id = kin.frame_id(tip_frame)
        self.variables: tuple[str, ...] = self._variables(joints)
        parent = kin.model.frames[tip_id].parentJoint
        path_ids = {int(j) for j in kin.model.supports[parent] if j != 0}
        lock = [j for j in range(1, kin.model.njoints) if j not in path_ids]
        self.model: pin.Model = pin.buildReducedModel(
            _renamed_locked(kin.model, lock), lock, pin.neutral(kin.model)
        )
        self.data: pin.Data = self.model.createData()
        # the reduced model holds only the path joints, root to tip, velocity index = order
        self.path: tuple[str, ...] = tuple(self.model.names[1:])
        self.frame_id = int(self.model.getFrameId(tip_frame))
        self._build_maps()
        self.lower, self.upper = self._limits()
        self.continuous = np.array([kin.joints[v].continuous for v in self.variables], bool)
        self._wraps = bool(self.continuous.any())
        self._followers = self._mimic_followers()

    def _variables(self, joints: Iterable[str]) -> tuple[str, ...]:
        out: list[str] = []
        for name in joints:
            self.kin.joint(name)
            mimic = self.kin.robot_model.joints[name].mimic
            master = mimic.joint if mimic is not None else name
            if master not in out:
                out.append(master)
        return tuple(out)

    def _build_maps(self) -> None:
        n, p = len(self.variables), len(self.path)
        self.a = np.zeros((p, n))
        self.b_fixed = np.zeros(p)
        self.held: list[int] = []  # path rows held at their seed value
        index = {v: k for k, v in enumerate(self.variables)}
        for row, name in enumerate(self.path):
            mimic = self.kin.robot_model.joints[name].mimic
            if name in index:
                self.a[row, index[name]] = 1.0
            elif mimic is not None and mimic.joint in index:
                self.a[row, index[mimic.joint]] = mimic.multiplier
                self.b_fixed[row] = mimic.offset
            else:
                self.held.append(row)
        self.identity_map = n == p and not self.held and np.array_equal(self.a, np.eye(n))
        # the path row each variable moves alone, when each moves one row one to one (no
        # mimic follower on the path): then ``J @ A`` is a choice of J's columns
        rows = [np.flatnonzero(column) for column in self.a.T]
        self._columns: NDArray[np.intp] | None = None
        if all(r.size == 1 and self.a[r[0], k] == 1.0 for k, r in enumerate(rows)):
            self._columns = np.array([int(r[0]) for r in rows], dtype=np.intp)
        moved = np.flatnonzero(np.any(self.a != 0.0, axis=1))
        # the first path row a variable moves; the rows before it are held
        self.first_row = int(moved[0]) if moved.size else p
        ids = [self.model.getJointId(name) for name in self.path]
        cont = [self.model.joints[j].nq == 2 for j in ids]
        idx_q = np.array([self.model.joints[j].idx_q for j in ids], dtype=int)
        self.rev_rows = np.array([r for r in range(p) if not cont[r]], dtype=int)
        self.cont_rows = np.array([r for r in range(p) if cont[r]], dtype=int)
        self.rev_q = idx_q[self.rev_rows]
        self.cos_q = idx_q[self.cont_rows]
        self.sin_q = self.cos_q + 1

    def _limits(self) -> tuple[FloatArray, FloatArray]:
        """Variable bounds, narrowed so that every mimic follower stays in its own limits.

        A joint with ``<safety_controller>`` soft limits is bounded by them: a real robot's
        controllers (the PR2's) stop it there, so a solution beyond them ends off target.
        """
        lower = np.array([self._working(v)[0] for v in self.variables])
        upper = np.array([self._working(v)[1] for v in self.variables])
        index = {v: k for k, v in enumerate(self.variables)}
        for joint in self.kin.robot_model.joints.values():
            m = joint.mimic
            if m is None or m.joint not in index or joint.name not in self.kin.joints:
                continue
            info, k = self.kin.joints[joint.name], index[m.joint]
            if m.multiplier == 0 or info.continuous:
                continue
            lo, hi = sorted(
                ((info.lower - m.offset) / m.multiplier, (info.upper - m.offset) / m.multiplier)
            )
            lower[k], upper[k] = max(lower[k], lo), min(upper[k], hi)
        return lower, upper

    def offsets(self, seed: Mapping[str, float]) -> FloatArray:
        """``b`` of ``value = A @ x + b``: held joints at their seed value (else default)."""
        b = self.b_fixed.copy()
        for row in self.held:
            name = self.path[row]
            b[row] = float(seed[name]) if name in seed else self.kin.default_value(name)
        return b

    def configuration(self, x: FloatArray, b: FloatArray) -> FloatArray:
        """Reduced-model configuration of variable values ``x``."""
        if self.identity_map:
            values = x
        elif self._columns is not None:
            values = b.copy()
            values[self._columns] = x
        else:
            values = self.a @ x + b
        q = np.empty(self.model.nq)
        q[self.rev_q] = values[self.rev_rows]
        c = values[self.cont_rows]
        q[self.cos_q] = np.cos(c)
        q[self.sin_q] = np.sin(c)
        return q

    def variable_jacobian(self, jac: FloatArray) -> FloatArray:
        """``jac @ A``: a Jacobian of the path's joints as one of the variables."""
        if self.identity_map:
            return jac
        if self._columns is not None:
            return jac.take(self._columns, axis=1)  # C order, as the product: same sums
        return jac @ self.a

    def tip_pose(self, x: FloatArray, b: FloatArray) -> pin.SE3:
        """Pose of the tip frame in the root link for variable values ``x``."""
        pin.framesForwardKinematics(self.model, self.data, self.configuration(x, b))
        return self.data.oMf[self.frame_id].copy()

    def _working(self, variable: str) -> tuple[float, float]:
        """The hard limits of ``variable`` narrowed to its soft limits, if it has any."""
        info = self.kin.joints[variable]
        joint = self.kin.robot_model.joints.get(variable)
        if joint is None or info.continuous:
            return info.lower, info.upper
        soft_lower, soft_upper = joint.working_limits
        return (
            info.lower if soft_lower is None else max(info.lower, soft_lower),
            info.upper if soft_upper is None else min(info.upper, soft_upper),
        )

    def _mimic_followers(self) -> tuple[tuple[str, str, float, float], ...]:
        """(follower, master, multiplier, offset) of every joint following a variable,
        transitively, in an order where masters come first (whole robot)."""
        probe = mimic_followers(self.kin.robot_model, dict.fromkeys(self.variables, 0.0))
        ordered: list[tuple[str, str, float, float]] = []
        known = set(self.variables)
        while len(known) < len(probe):
            for joint in self.kin.robot_model.joints.values():
                m = joint.mimic
                if joint.name in probe and joint.name not in known and m and m.joint in known:
                    ordered.append((joint.name, m.joint, m.multiplier, m.offset))
                    known.add(joint.name)
        return tuple(ordered)

    def joint_positions(self, x: FloatArray) -> dict[str, float]:
        """Variable values by name, plus every mimic follower of them (whole robot)."""
        values = dict(zip(self.variables, x.tolist(), strict=True))
        for name, master, multiplier, offset in self._followers:
            values[name] = multiplier * values[master] + offset
        return values

    def wrap_continuous(self, x: FloatArray, reference: FloatArray) -> FloatArray:
        """Shift continuous variables by whole turns to lie within pi of ``reference``."""
        if not self._wraps:
            return x
        # ``np.round`` to 0 decimals is ``rint``, called through two Python layers
        turns = np.rint((x - reference) / (2 * math.pi))
        return np.where(self.continuous, x - turns * 2 * math.pi, x)

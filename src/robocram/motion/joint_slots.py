"""Where a checker's joints (and their mimic followers) sit in pinocchio's ``q``.

A checker is given values of a few joints; pinocchio wants the whole robot's configuration,
with continuous joints as (cos, sin) and mimic joints following their masters. The rest
of ``q`` stays as the robot stood when the checker was made.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import RobotKinematics
from robocram.motion.errors import MotionError
from robocram.motion.mimic_family import mimic_family
from robocram.robots import RobotModel


class JointSlots:
    """Fills pinocchio configurations from values of :attr:`names`, around ``q0``."""

    def __init__(
        self, kin: RobotKinematics, joints: Sequence[str], q0: NDArray[np.float64]
    ) -> None:
        self.q0 = q0
        self.names = tuple(joints)
        self.width = len(self.names)
        tables = kin.robot_model.derived(_slot_tables)
        found = tables.get(self.names)
        if found is None:
            found = tables[self.names] = _slots(kin, self.names)
        (
            self.plain_src, self.plain_idx, self.plain_mult, self.plain_off,
            self.cont_src, self.cont_idx, self.cont_mult, self.cont_off,
        ) = found  # fmt: skip

    def full(self, q: Sequence[float] | NDArray[np.float64]) -> NDArray[np.float64]:
        """The robot's pinocchio configuration with the joints at ``q``."""
        values = np.asarray(q, dtype=float)
        if values.shape != (self.width,):
            raise MotionError(
                f"a configuration gives {self.width} values, for joints {list(self.names)}; "
                f"got shape {values.shape}"
            )
        full = self.q0.copy()
        full[self.plain_idx] = self.plain_mult * values[self.plain_src] + self.plain_off
        if len(self.cont_idx):
            angles = self.cont_mult * values[self.cont_src] + self.cont_off
            full[self.cont_idx] = np.cos(angles)
            full[self.cont_idx + 1] = np.sin(angles)
        return full


_Slots = tuple[
    NDArray[np.int_], NDArray[np.int_], NDArray[np.float64], NDArray[np.float64],
    NDArray[np.int_], NDArray[np.int_], NDArray[np.float64], NDArray[np.float64],
]  # fmt: skip


def _slot_tables(model: RobotModel) -> dict[tuple[str, ...], _Slots]:
    """Per planned joints: their slots, kept with the model (a checker is made per motion,
    and its joints repeat; the arrays are only read)."""
    return {}


def _slots(kin: RobotKinematics, names: tuple[str, ...]) -> _Slots:
    """The plain then the continuous slots of ``names`` and their followers: source
    value, q index, multiplier, offset."""
    rows: list[tuple[int, int, float, float, bool]] = []  # (source, idx_q, mult, off, cont)
    for source, name in enumerate(names):
        for follower, mult, off in mimic_family(kin.robot_model, name):
            info = kin.joint(follower)
            rows.append((source, info.idx_q, mult, off, info.continuous))
    plain = [r for r in rows if not r[4]]
    cont = [r for r in rows if r[4]]
    return (
        np.array([r[0] for r in plain], dtype=int),
        np.array([r[1] for r in plain], dtype=int),
        np.array([r[2] for r in plain]),
        np.array([r[3] for r in plain]),
        np.array([r[0] for r in cont], dtype=int),
        np.array([r[1] for r in cont], dtype=int),
        np.array([r[2] for r in cont]),
        np.array([r[3] for r in cont]),
    )

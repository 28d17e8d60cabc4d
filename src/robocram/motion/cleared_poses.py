"""Base poses the exact check has answered, kept for the checker's life.

A drive asks the exact check again about poses it answered before: every tree edge OMPL
grows from a node starts at that node, and every detour starts where the robot stands.
While the checker lives only the robot moves, so a pose's answer stands; and a pose the
exact check cleared with a gap (nothing nearer than that, beyond the contact distance)
clears every pose that moves no point of the robot as far: its gap, less that travel, is
a gap there too.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from robocram.motion.robot_footprint import FloatArray


@dataclass
class ClearedPoses:
    """Answers of the exact check by pose ``(x, y, yaw)``: a gap [m] or None (blocked)."""

    reach: float  # [m] farthest any point of the robot is from the base origin
    _answers: dict[bytes, float | None] = field(default_factory=dict)
    # cleared with a gap > 0: the first ``_count`` rows, grown by doubling (a planning query
    # asks thousands of times; stacking a list of poses each time cost more than the test)
    _poses: FloatArray = field(default_factory=lambda: np.empty((8, 3)))
    _gaps: FloatArray = field(default_factory=lambda: np.empty(8))
    _count: int = 0

    def add(self, pose: FloatArray, gap: float | None) -> None:
        """Keep the exact check's answer at ``pose``."""
        self._answers[pose.tobytes()] = gap
        if gap is not None and gap > 0.0:
            if self._count == len(self._gaps):
                self._poses = np.concatenate([self._poses, np.empty_like(self._poses)])
                self._gaps = np.concatenate([self._gaps, np.empty_like(self._gaps)])
            self._poses[self._count] = pose
            self._gaps[self._count] = gap
            self._count += 1

    def known(self, pose: FloatArray) -> tuple[bool, float | None]:
        """``(True, answer)`` when the answer at ``pose`` follows from those kept (the
        largest gap a cleared pose leaves there), else ``(False, None)``."""
        key = pose.tobytes()
        if key in self._answers:
            return True, self._answers[key]
        if not self._count:
            return False, None
        step = pose[None, :] - self._poses[: self._count]
        turn = np.abs((step[:, 2] + np.pi) % (2.0 * np.pi) - np.pi)
        left = self._gaps[: self._count] - (np.hypot(step[:, 0], step[:, 1]) + self.reach * turn)
        best = float(left.max())
        return (True, best) if best > 0.0 else (False, None)

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
    _poses: list[FloatArray] = field(default_factory=list)  # cleared with a gap > 0
    _gaps: list[float] = field(default_factory=list)

    def add(self, pose: FloatArray, gap: float | None) -> None:
        """Keep the exact check's answer at ``pose``."""
        self._answers[pose.tobytes()] = gap
        if gap is not None and gap > 0.0:
            self._poses.append(pose.copy())
            self._gaps.append(gap)

    def known(self, pose: FloatArray) -> tuple[bool, float | None]:
        """``(True, answer)`` when the answer at ``pose`` follows from those kept (the
        largest gap a cleared pose leaves there), else ``(False, None)``."""
        key = pose.tobytes()
        if key in self._answers:
            return True, self._answers[key]
        if not self._poses:
            return False, None
        kept = np.asarray(self._poses)
        step = pose[None, :] - kept
        turn = np.abs((step[:, 2] + np.pi) % (2.0 * np.pi) - np.pi)
        left = np.asarray(self._gaps) - (np.hypot(step[:, 0], step[:, 1]) + self.reach * turn)
        best = float(left.max())
        return (True, best) if best > 0.0 else (False, None)

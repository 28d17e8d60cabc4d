"""A Cartesian line spares clearance queries its last waypoint's clearance answers."""

from __future__ import annotations

import numpy as np

from robocram.motion.cartesian_path import _Clearance
from robocram.motion.configuration_checker import Configuration, LinkPair


class _Wall:
    """One joint moving a point towards a wall 0.1 m away: clearance 0.1 - q [m]."""

    joints = ("slide",)
    reach = 1.0

    def __init__(self) -> None:
        self.asked: list[float] = []

    def clearance(self, q: Configuration) -> float:
        self.asked.append(float(q[0]))
        return 0.1 - float(q[0])

    def clearances(self, q: Configuration) -> dict[str, float]:
        return {"point": self.clearance(q)}

    def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
        return [("point", "wall")] if float(q[0]) >= 0.1 else []

    def is_free(self, q: Configuration) -> bool:
        return not self.colliding(q)


def test_a_step_well_inside_the_last_clearance_is_free_without_a_query() -> None:
    wall = _Wall()
    clearance = _Clearance(wall)
    free = [clearance.step_free(np.array([0.01 * k]), 0.01) for k in range(1, 12)]
    # clear by 0.09 at the first step (asked): the next ones follow from it until the
    # bound left, less two steps, no longer exceeds a step; then it asks at every step
    assert wall.asked == [0.01, 0.1, 0.11]
    for k, ok in enumerate(free, start=1):
        assert ok == (0.1 - 0.01 * k > 0.01)  # what asking every time would say


def test_a_checker_without_clearances_is_never_spared() -> None:
    class Plain:
        joints = ("slide",)

        def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
            return []

        def is_free(self, q: Configuration) -> bool:
            return True

    clearance = _Clearance(Plain())
    assert not clearance.step_free(np.array([0.01]), 0.01)
    assert not clearance.step_free(np.array([0.02]), 0.01)

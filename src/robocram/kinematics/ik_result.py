"""The answer of an IK query: joint values and how close they bring the tool to the target."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from robocram.kinematics.planar_base import BaseMotion


@dataclass(frozen=True)
class IKResult:
    """Outcome of :func:`~robocram.kinematics.solve_ik`; truthy when it succeeded.

    ``joint_positions`` holds the arm joints, the torso joint when it was allowed to move,
    and every mimic joint following them, [rad | m]; ``base_motion`` the base's move when
    IK could move the base (``IKOptions(base=PlanarBase())``). On failure it holds the best
    configuration found (closest to the target), still within limits. Errors are those of
    that configuration: ``position_error`` [m], ``orientation_error`` [rad].

    Why it failed, for messages that advise only what applies: ``colliding_pairs`` are the
    ``(robot link, other)`` pairs the collision check reported for the rejected solutions
    (most frequent first), ``beyond_reach`` [m] how far the target lies outside the arm's
    reach bound (0 when it may be reachable).
    """

    success: bool
    joint_positions: Mapping[str, float] = field(default_factory=dict)
    position_error: float = float("inf")  # [m]
    orientation_error: float = float("inf")  # [rad]
    iterations: int = 0
    restarts: int = 0
    elapsed: float = 0.0  # [s]
    rejected_in_collision: int = 0  # converged solutions the collision check refused
    colliding_pairs: tuple[tuple[str, str], ...] = ()
    beyond_reach: float = 0.0  # [m]
    base_motion: BaseMotion | None = None  # None when the base was not part of the query

    def __bool__(self) -> bool:
        return self.success

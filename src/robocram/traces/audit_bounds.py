"""The bounds a run's audit holds its trajectories to, in one frozen value.

Depths: a robot link or held object may penetrate another body by at most
``penetration`` (1 mm; PyBullet's own contacts sit within a fraction of that), a hand the
object its arm holds by ``held_depth`` (5 mm), the floor by any depth. Limits: a
derivative may exceed its limit by ``limit_tolerance`` (5 %) of it, plus the rounding error
of its difference quotient. Density: checked configurations are at most ``joint_step``
(0.005 rad or m) apart in every joint, and no point of the robot or what it holds moves
more than ``point_step`` (5 mm) between them. Jumps: a joint or the base may change by
``teleport`` (1e-4 rad or m) without a trajectory.

``skipped_self_pairs(robot)`` says which pairs of a robot's own links are not
judged: by default the adjacent ones (:func:`~robocram.traces.link_adjacency.adjacent_links`
of its model) and those the robot's self-collision matrix skips (:func:`matrix_pairs_of`);
``adjacent_pairs_of`` judges every other pair.
"""

from __future__ import annotations

from collections.abc import Callable, Collection
from dataclasses import dataclass, field

from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.traces.errors import TraceArgumentError
from robocram.traces.link_adjacency import LinkPair, adjacent_links
from robocram.world import RobotHandle

SkippedSelfPairs = Callable[[RobotHandle], Collection[LinkPair]]  # robot -> pairs


def adjacent_pairs_of(robot: RobotHandle) -> frozenset[LinkPair]:
    """The adjacent pairs of ``robot``'s links, as the audit works them out itself."""
    return adjacent_links(robot.description.model)


def matrix_pairs_of(robot: RobotHandle) -> frozenset[LinkPair]:
    """The pairs the audit skips by default: its own adjacent ones and those the robot's
    :class:`~robocram.motion.self_collision_matrix.SelfCollisionMatrix` skips (convex
    hulls that always overlap, or at rest, or bridge a flexed joint; pairs the
    description allows). Only which pairs are read from it: every distance is the
    audit's own."""
    matrix = SelfCollisionMatrix.of(robot)
    return adjacent_pairs_of(robot) | frozenset(matrix.skipped)


@dataclass(frozen=True)
class AuditBounds:
    """What the audit allows; see the module docstring for each bound."""

    penetration: float = 0.001  # [m] deepest contact of anything not allowed
    held_depth: float = 0.005  # [m] a hand into the object its arm holds
    limit_tolerance: float = 0.05  # share of a limit a derivative may exceed it by
    joint_step: float = 0.005  # [rad | m] between checked configurations, per joint
    point_step: float = 0.005  # [m] any point of the robot between checked configurations
    teleport: float = 1e-4  # [rad | m] a change without a trajectory
    skipped_self_pairs: SkippedSelfPairs = field(default=matrix_pairs_of)

    def __post_init__(self) -> None:
        for name in ("penetration", "held_depth", "limit_tolerance", "teleport"):
            if not getattr(self, name) >= 0.0:
                raise TraceArgumentError(
                    f"audit bound {name} must be >= 0, got {getattr(self, name)}"
                )
        for name in ("joint_step", "point_step"):
            if not getattr(self, name) > 0.0:
                raise TraceArgumentError(
                    f"audit step {name} must be > 0, got {getattr(self, name)}"
                )

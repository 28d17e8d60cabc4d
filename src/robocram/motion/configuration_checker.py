"""What a planner asks of a collision model: is this configuration free, and if not, why.

Planners work on configurations ``q`` of a fixed tuple of joints; everything else (the
base, the other joints, the world) stays as it was when the checker was made. Three
implementations: :class:`~robocram.motion.bullet_scene.BulletScene` (the projection
world itself), :class:`~robocram.motion.coal_clearance.CoalClearance` (clearances from
coal, contacts from a ``BulletScene``) and the coal scene (a snapshot, for OMPL).
"""

from __future__ import annotations

import contextlib
from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol, TypeGuard, runtime_checkable

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from robocram.motion.joint_levers import LeverData

Configuration = Sequence[float] | npt.NDArray[np.float64]  # values of the checker's joints
LinkPair = tuple[str, str]  # (robot link, other: object, object/link or robot link)


class ConfigurationChecker(Protocol):
    """Checks configurations of :attr:`joints`; used by one thread at a time."""

    @property
    def joints(self) -> tuple[str, ...]:
        """The joints a configuration gives values for, in order."""
        ...

    def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
        """The colliding ``(robot link, other)`` pairs at ``q`` (empty: free)."""
        ...

    def is_free(self, q: Configuration) -> bool:
        """Whether ``q`` collides with nothing (the fast path)."""
        ...


@runtime_checkable
class ClearanceChecker(ConfigurationChecker, Protocol):
    """A checker that also tells how far a configuration is from touching anything."""

    @property
    def reach(self) -> float:
        """How far [m] its clearance queries look: farther is reported as this."""
        ...

    def clearance(self, q: Configuration) -> float:
        """The distance [m] from the moving links to what they may not touch (<= 0: touch)."""
        ...

    def clearances(self, q: Configuration) -> dict[str, float]:
        """Per moving link (or held object) near something: that distance [m]; the links
        not named are clear by the checker's reach."""
        ...


@runtime_checkable
class LeverChecker(ClearanceChecker, Protocol):
    """A clearance checker that can also bound how fast its links move, as posed now."""

    def lever_links(self) -> tuple[str, ...]:
        """The links (and held objects) that move: what :meth:`joint_levers` rows are."""
        ...

    def joints_after(self) -> npt.NDArray[np.bool_]:
        """``[i, k]``: whether joint k sits below joint i (k's motion changes i's levers)."""
        ...

    def joint_levers(self, links: Sequence[str]) -> npt.NDArray[np.float64]:
        """Per link, per joint: the most [m] a point of it moves per unit joint change."""
        ...

    def link_speeds(
        self, links: Sequence[str], delta: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.float64]:
        """Per link: the most [m] a point of it moves per unit of a segment whose joints
        change by ``delta``, as posed now."""
        ...

    def lever_data(self) -> LeverData:
        """What the levers need beyond the frames: radii, which joints are prismatic."""
        ...


class LabelGaps(Protocol):
    """A check's near labels (moving links or held objects), each with a lower bound on its
    gap, measured one by one: the labels whose bound cannot limit a step are never
    measured."""

    names: list[str]  # the labels whose bound is below the checker's reach
    bounds: list[float]  # [m] per label: at most its gap

    def gap(self, k: int) -> float:
        """Label ``k``'s gap [m] (<= 0: near enough that the contact check must decide);
        the reach if it is farther."""
        ...


@runtime_checkable
class NearChecker(LeverChecker, Protocol):
    """A lever checker that poses a configuration and tells its near labels' bounds
    before measuring any gap."""

    def near(self, q: Configuration) -> LabelGaps:
        """The labels near something at ``q``, the robot posed there."""
        ...


def can_tell_clearance(checker: object) -> TypeGuard[ClearanceChecker]:
    """``isinstance(checker, ClearanceChecker)``, asked once per class: a protocol check
    compares every member (~20 us), and a motion asks it per segment and per waypoint."""
    return _is_a(checker, ClearanceChecker)


def can_tell_levers(checker: object) -> TypeGuard[LeverChecker]:
    """``isinstance(checker, LeverChecker)``, asked once per class."""
    return _is_a(checker, LeverChecker)


def can_tell_near(checker: object) -> TypeGuard[NearChecker]:
    """``isinstance(checker, NearChecker)``, asked once per class."""
    return _is_a(checker, NearChecker)


def _is_a(checker: object, protocol: type) -> bool:
    """The first instance of a class answers for the class (checkers set every member
    in ``__init__``; ``issubclass`` refuses protocols with data members)."""
    key = (type(checker), protocol)
    found = _KINDS.get(key)
    if found is None:
        found = _KINDS[key] = isinstance(checker, protocol)
    return found


_KINDS: dict[tuple[type, type], bool] = {}  # (checker class, protocol) -> is one


def posed(checker: ConfigurationChecker) -> contextlib.AbstractContextManager[None]:
    """The checker's ``posed()`` block (a world checker puts the robot back once, at the
    end, instead of after every check), or a block that does nothing."""
    hold = getattr(checker, "posed", None)
    return hold() if hold is not None else contextlib.nullcontext()

"""Errors of the costmaps layer: one root, :class:`CostmapError`, with data-carrying kinds."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from robocram.costmaps.location_advice import not_found_advice
from robocram.costmaps.location_blame import Culprits, culprit_sentence
from robocram.designators import GroundingError


class CostmapError(Exception):
    """Root of every error raised by :mod:`robocram.costmaps`."""


class CostmapInputError(CostmapError, ValueError):
    """A costmap or a location designator was given a value it cannot use.

    Attributes:
        culprit: the offending key, object name or value.
    """

    def __init__(self, message: str, culprit: object) -> None:
        super().__init__(message)
        self.culprit = culprit


class LocationOutsideArea(CostmapInputError):
    """A location searched round a point outside the world's planning area: no stand or
    spot there is one the robot can mean (a typo in a coordinate, another frame).

    Attributes:
        culprit: the point (map x, y, z [m]).
        area: the :class:`~robocram.world.PlanningArea` it lies outside.
    """

    def __init__(self, message: str, point: object, area: object) -> None:
        super().__init__(message, point)
        self.area = area


class LocationKeyError(CostmapInputError):
    """A location designator uses a key no rule knows, or two keys that exclude each other."""

    def __init__(self, message: str, key: str, designator: object = None) -> None:
        super().__init__(message, key)
        self.key = key
        self.designator = designator


class LocationNotFound(CostmapError, GroundingError):
    """CRAM's 30 candidates in a row were rejected: the designator has no (more) pose.

    Attributes:
        rejections: how many candidates each validator rejected in all, by validator name.
        accepted: how many poses the designator had yielded before.
        emptied_by: the cost layers that left no cell (when there were no candidates).
        occluded_by: the objects that hid the target from (nearly) every refused candidate,
            most frequent first (``("box-3",)``); empty when no object was to blame.
        blocked_by: the objects the robot would have touched at (nearly) every refused
            stand, standing or reaching, most frequent first.
        culprits: the same with how often each was blamed (what the message says).
        area: the side [m] of the square searched (its ``size``), None if not known.
    """

    def __init__(
        self,
        designator: Any,
        rejections: Mapping[str, int],
        accepted: int,
        in_a_row: int,
        emptied_by: tuple[str, ...] = (),
        culprits: Culprits | None = None,
        area: float | None = None,
    ) -> None:
        self.rejections = dict(rejections)
        self.area = area
        self.accepted = accepted
        self.in_a_row = in_a_row
        self.emptied_by = emptied_by
        self.culprits = culprits
        self.description: str = designator.description
        self.occluded_by = culprits.occluded_by if culprits else ()
        self.blocked_by = culprits.blocked_by if culprits else ()
        advice = not_found_advice(self.rejections, accepted, in_a_row, emptied_by, area)
        if culprits:  # the named objects first: the most specific remedy
            advice = f"{culprit_sentence(culprits)}; {advice}"
        counts = ", ".join(f"{name} rejected {n}" for name, n in sorted(self.rejections.items()))
        GroundingError.__init__(
            self,
            f"{designator.description}: no location found after {in_a_row} "
            f"rejections in a row ({counts or 'no candidates at all'}; {accepted} accepted "
            f"before); {advice}",
            designator,
        )

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle (batches send failures across processes) with the designator's description
        in its place: a live designator holds its resolver's lock."""
        return (
            type(self),
            (
                DescribedAs(self.description),
                self.rejections,
                self.accepted,
                self.in_a_row,
                self.emptied_by,
                self.culprits,
                self.area,
            ),
        )


@dataclass(frozen=True)
class DescribedAs:
    """A designator's description standing in for it where the designator cannot go."""

    description: str


class CostmapUsageError(CostmapError, TypeError):
    """A costmap was handed the wrong kind of thing: the caller's mistake."""

    summary = "a costmap was handed the wrong kind of thing"
    hint = "pass what the message asks for"

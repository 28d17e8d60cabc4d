"""Location designators: resolved by the current :class:`LocationResolver`, lazily.

``a.location(pose=p)`` resolves to ``p`` with the default resolver; richer descriptions
(``(horizontal_position right)``, ``(near table)``) need generators that understand them.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from robocram.designators.designator import Designator, Kind
from robocram.designators.errors import GroundingError
from robocram.designators.location_resolver import LocationResolver, current_location_resolver


class LocationDesignator(Designator):
    """A description of a place, e.g. ``(a location (pose p))`` or ``(a location (on table))``."""

    kind = Kind.LOCATION

    def reference(self, kb: Any = None, *, resolver: LocationResolver | None = None) -> Any:
        """Return the first accepted pose (cached); ``resolver`` overrides the current one."""
        return super().reference(resolver if resolver is not None else kb)

    def next_solution(
        self, kb: Any = None, *, resolver: LocationResolver | None = None
    ) -> Designator | None:
        """Return a designator for the next accepted pose, or None when the stream ends."""
        return super().next_solution(resolver if resolver is not None else kb)

    def _resolution_context(self, kb: Any) -> object:
        return kb if isinstance(kb, LocationResolver) else current_location_resolver()

    def _solutions(self, context: Any) -> Iterator[Any]:
        return context.solutions(self)

    def _no_solution_error(self, context: Any) -> GroundingError:
        resolver: LocationResolver = context
        generators = [g.name for g in resolver.generators]
        validators = [v.name for v in resolver.validators]
        return GroundingError(
            f"{self.description} has no solution: generators {generators} proposed no candidate "
            f"that validators {validators} took (the stream ends after "
            f"{resolver.max_consecutive_rejections} rejections in a row); register a generator "
            "that understands its properties, e.g. with scoped_location_generator",
            self,
        )

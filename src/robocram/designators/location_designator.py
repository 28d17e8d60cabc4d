"""Location designators: resolved by the current :class:`LocationResolver`, lazily.

``a.location(pose=p)`` resolves to ``p`` with the default resolver; richer descriptions
(``(horizontal_position right)``, ``(near table)``) need generators that understand them.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from robocram.designators.designator import Designator, Kind
from robocram.designators.errors import GroundingError
from robocram.designators.location_resolver import LocationResolver, current_location_resolver

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase


class LocationDesignator(Designator[object]):
    """A description of a place, e.g. ``(a location (pose p))`` or ``(a location (on table))``."""

    kind = Kind.LOCATION

    def reference(
        self, kb: KnowledgeBase | None = None, *, resolver: LocationResolver | None = None
    ) -> object:
        """Return the first accepted pose (cached); ``resolver`` overrides the current one.

        ``kb`` is ignored: locations are resolved by the resolver, not by Prolog.
        """
        return self._reference_in(resolver if resolver is not None else current_location_resolver())

    def next_solution(
        self, kb: KnowledgeBase | None = None, *, resolver: LocationResolver | None = None
    ) -> Designator[object] | None:
        """Return a designator for the next accepted pose, or None when the stream ends."""
        return self._next_in(resolver if resolver is not None else current_location_resolver())

    def _resolution_context(self, kb: KnowledgeBase | None) -> LocationResolver:
        return current_location_resolver()

    def _solutions(self, context: LocationResolver) -> Iterator[object]:
        return context.solutions(self)

    def _no_solution_error(self, context: object) -> GroundingError:
        resolver = context if isinstance(context, LocationResolver) else LocationResolver()
        generators = [g.name for g in resolver.generators]
        validators = [v.name for v in resolver.validators]
        return GroundingError(
            f"{self.description} has no solution: generators {generators} proposed no candidate "
            f"that validators {validators} took (the stream ends after "
            f"{resolver.max_consecutive_rejections} rejections in a row); register a generator "
            "that understands its properties, e.g. with scoped_location_generator",
            self,
        )

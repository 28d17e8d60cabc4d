"""Object and human designators: not reasoned about, filled in by perception.

Perception answers ``(an object (type bottle))`` with a new designator that carries the
perceived data (pose, name, ...) and is equated with the one asked for:
``found = wanted.make_effective(data, pose=p)``. Then ``wanted.current_desig() is found``.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from robocram.designators.designator import Designator, Kind, Quantifier
from robocram.designators.errors import DesignatorArgumentError, GroundingError
from robocram.designators.properties import PropertyPair

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase


class ObjectDesignator(Designator[object]):
    """A description of a thing; its solution is the data perception attached to it."""

    kind = Kind.OBJECT

    def __init__(
        self,
        *pairs: PropertyPair,
        quantifier: Quantifier = Quantifier.A,
        data: object = None,
        **properties: object,
    ) -> None:
        super().__init__(*pairs, quantifier=quantifier, **properties)
        self._data = data

    @property
    def data(self) -> Any:
        """The data perception attached (None until perceived)."""
        return self._data

    @property
    def effective(self) -> bool:
        """Whether perception has attached data to this very designator."""
        return self._data is not None

    def make_effective(self, data: object, **new_properties: object) -> ObjectDesignator:
        """Return a designator with the perceived ``data`` and properties, equated with this one.

        New properties replace same-named old ones; the others are kept.
        """
        if data is None:
            raise DesignatorArgumentError(
                f"make_effective of {self.description} needs data, got None"
            )
        kept = [(k, v) for k, v in self.properties if k not in new_properties]
        successor = type(self)(*kept, quantifier=self.quantifier, data=data, **new_properties)
        self.current_desig().equate(successor)
        return successor

    def reference(self, kb: KnowledgeBase | None = None) -> object:
        """Return the perceived data of this designator.

        Raises:
            GroundingError: nothing was perceived for this designator yet.
        """
        if self._data is None:
            raise self._no_solution_error(None)
        return self._data

    def solutions(self, kb: KnowledgeBase | None = None) -> Iterator[object]:
        """Yield the perceived data, if any."""
        if self._data is not None:
            yield self._data

    def next_solution(self, kb: KnowledgeBase | None = None) -> Designator[object] | None:
        """Return None: perceived data has exactly one solution, the data itself."""
        return None

    def _no_solution_error(self, context: object) -> GroundingError:
        newest = self.current_desig()
        hint = (
            f"; its newest equated designator {newest.description} has data: use current_desig()"
            if newest is not self and getattr(newest, "data", None) is not None
            else "; perceive it first (perform a detecting motion), which fills in the data"
        )
        return GroundingError(f"{self.description} has no perceived data{hint}", self)


class HumanDesignator(ObjectDesignator):
    """A description of a person; like an object, perception fills in its data."""

    kind = Kind.HUMAN

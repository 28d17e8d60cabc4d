"""The designator: a symbolic description that is resolved lazily into a solution.

A designator holds ordered ``(key, value)`` properties. Each kind resolves them its own way
(motions and actions by Prolog grounding rules, locations by generators and validators,
objects by perception). ``Designator[S]`` resolves to values of type ``S`` (a motion to a
command ``Term``). ``reference()`` returns the first solution and caches it;
``next_solution()`` gives a new designator, equated with this one, for the next solution.
Designators equated together form a chain (CRAM's ``first-desig``/``current-desig``).
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from enum import Enum
from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar

from robocram.designators.errors import DesignatorError, GroundingError
from robocram.designators.properties import PropertyPair, format_value, normalize_properties
from robocram.designators.solution_stream import SolutionStream

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase, Value

S = TypeVar("S")  # a solution, in the stream tables
S_co = TypeVar("S_co", covariant=True)  # what a designator resolves to

_CHAIN_LOCK = threading.RLock()  # guards the parent/successor links of every chain


class Kind(Enum):
    """The kinds of designators CRAM knows."""

    ACTION = "action"
    MOTION = "motion"
    LOCATION = "location"
    OBJECT = "object"
    HUMAN = "human"


class Quantifier(Enum):
    """``a``/``an`` describe one entity, ``all`` every entity that fits."""

    A = "a"
    ALL = "all"


class _StreamTable(Generic[S]):
    """Solution streams of one designator family, one per resolution context (a KB, a resolver).

    Keyed by context so the same designator referenced under two environments never hands
    out the solution of the other one.
    """

    def __init__(self) -> None:
        self._streams: dict[int, tuple[object, SolutionStream[S]]] = {}
        self._lock = threading.Lock()

    def stream(self, context: object, source: Callable[[], Iterator[S]]) -> SolutionStream[S]:
        with self._lock:
            entry = self._streams.get(id(context))
            if entry is None or entry[0] is not context:
                entry = (context, SolutionStream(source()))
                self._streams[id(context)] = entry
            return entry[1]


class Designator(Generic[S_co]):
    """Base of all designator kinds, resolving to ``S``; subclasses say how solutions come."""

    kind: ClassVar[Kind]

    def __init__(
        self,
        *pairs: PropertyPair,
        quantifier: Quantifier = Quantifier.A,
        **properties: object,
    ) -> None:
        self._properties = normalize_properties(pairs, properties)
        self.quantifier = quantifier
        self._streams: _StreamTable[S_co] = _StreamTable()
        self._index = 0
        self._parent: Designator[Any] | None = None
        self._successor: Designator[Any] | None = None
        self._check()

    def _check(self) -> None:
        """Validate the properties of a fresh designator (hook for kinds with requirements)."""

    @property
    def properties(self) -> tuple[PropertyPair, ...]:
        """The properties in the order written, repeats included."""
        return self._properties

    def get(self, key: str, default: object = None) -> Value:
        """Return the first value of property ``key``, or ``default``."""
        return next((v for k, v in self._properties if k == key), default)

    def get_all(self, key: str) -> list[Value]:
        """Return every value of property ``key`` (keys may repeat)."""
        return [v for k, v in self._properties if k == key]

    @property
    def type(self) -> Value:
        """The ``type`` property (None if absent)."""
        return self.get("type")

    @property
    def description(self) -> str:
        """The designator written the CRAM way, e.g. ``(a motion (type moving) (goal ...))``."""
        noun = self.kind.value if self.quantifier is Quantifier.A else f"{self.kind.value}s"
        article = "an" if self.quantifier is Quantifier.A and noun[0] in "aeiou" else "a"
        if self.quantifier is Quantifier.ALL:
            article = "all"
        props = "".join(f" ({k} {format_value(v)})" for k, v in self._properties)
        return f"({article} {noun}{props})"

    def __str__(self) -> str:
        return self.description

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.description}>"

    def reference(self, kb: KnowledgeBase | None = None) -> S_co:
        """Return this designator's solution (computed on first use, then cached).

        Raises:
            GroundingError: the designator has no solution in this context.
        """
        return self._reference_in(self._resolution_context(kb))

    def _reference_in(self, context: object) -> S_co:
        found = self._solution(context, self._index)
        if found is None:
            raise self._no_solution_error(context)
        return found[0]

    def next_solution(self, kb: KnowledgeBase | None = None) -> Designator[S_co] | None:
        """Return a designator for the next solution, equated with this one; None when exhausted."""
        return self._next_in(self._resolution_context(kb))

    def _next_in(self, context: object) -> Designator[S_co] | None:
        if self._solution(context, self._index + 1) is None:
            return None
        with _CHAIN_LOCK:
            successor = self._successor
            if successor is not None and successor._streams is self._streams:
                return successor
            sibling = self._copy()
            sibling._index = self._index + 1
            sibling._streams = self._streams
            self.equate(sibling)
            return sibling

    def solutions(self, kb: KnowledgeBase | None = None) -> Iterator[S_co]:
        """Yield this designator's solutions lazily, from its own onwards (shared cache)."""
        yield from self._solutions_in(self._resolution_context(kb))

    def _solutions_in(self, context: object) -> Iterator[S_co]:
        index = self._index
        while True:
            found = self._solution(context, index)
            if found is None:
                return
            yield found[0]
            index += 1

    def _solution(self, context: object, index: int) -> tuple[S_co] | None:
        stream = self._streams.stream(context, lambda: self._solutions(context))
        try:
            return stream.get(index)
        except DesignatorError:
            raise
        except Exception as err:
            raise GroundingError(
                f"resolving {self.description} failed: {type(err).__name__}: {err}", self
            ) from err

    def _copy(self) -> Designator[S_co]:
        twin = object.__new__(type(self))
        twin.__dict__.update(self.__dict__)
        twin._parent = None
        twin._successor = None
        twin._streams = _StreamTable()
        twin._index = 0
        return twin

    def _resolution_context(self, kb: KnowledgeBase | None) -> object:
        """Return the object solutions depend on (a KB, a location resolver...)."""
        raise NotImplementedError

    def _solutions(self, context: Any) -> Iterator[S_co]:
        """Yield this designator's solutions lazily in ``context``."""
        raise NotImplementedError

    def _no_solution_error(self, context: Any) -> GroundingError:
        return GroundingError(f"{self.description} has no solution", self)

    def equate(self, successor: Designator[object]) -> None:
        """Declare that ``successor`` describes the same entity, appending it to this chain."""
        if successor.kind is not self.kind:
            raise DesignatorError(
                f"cannot equate {self.description} with {successor.description}: "
                f"a {self.kind.value} designator can only be equated with another one",
                successor,
            )
        with _CHAIN_LOCK:
            if desig_equal(self, successor):
                return
            if successor._parent is not None:
                raise DesignatorError(
                    f"{successor.description} already follows {successor._parent.description}; "
                    "equate the first designator of its chain instead",
                    successor,
                )
            last = self.current_desig()
            last._successor = successor
            successor._parent = last

    def first_desig(self) -> Designator[object]:
        """Return the oldest designator of this chain."""
        with _CHAIN_LOCK:
            desig: Designator[object] = self
            while desig._parent is not None:
                desig = desig._parent
            return desig

    def current_desig(self) -> Designator[object]:
        """Return the newest designator of this chain (the best-informed description)."""
        with _CHAIN_LOCK:
            desig: Designator[object] = self
            while desig._successor is not None:
                desig = desig._successor
            return desig

    def chain(self) -> list[Designator[object]]:
        """Return the whole chain, oldest first."""
        with _CHAIN_LOCK:
            out = [self.first_desig()]
            while out[-1]._successor is not None:
                out.append(out[-1]._successor)
            return out


def desig_equal(a: Designator[object], b: Designator[object]) -> bool:
    """Return whether ``a`` and ``b`` belong to the same chain (describe the same entity)."""
    return a.first_desig() is b.first_desig()

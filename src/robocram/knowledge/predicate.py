"""One predicate of the table: its name, typed arguments, who provides it and what it means.

A :class:`Predicate` is the single place a predicate is described. From it come the
registrations of its Python implementation (:mod:`robocram.knowledge.registration`), the
typed queries plans use (:meth:`Predicate.answers`, :meth:`Predicate.first`), the facts a
description writes (:meth:`Predicate.fact`), the description check and the reference
page ``docs/predicates.md``. Users may still query the same predicates in Prolog.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from enum import Enum
from functools import cached_property
from typing import Any, Generic, Protocol, TypeVar

from robocram.knowledge.argument import Argument, arguments_of, to_prolog
from robocram.knowledge.errors import KnowledgeUsageError, UnknownArgumentError
from robocram.logic.terms import Term


class Source(Enum):
    """Who makes a predicate true."""

    DESCRIPTION = "description"  # facts a robot description provides
    WORLD = "world"  # computed by the world (first argument: the world, bound by world/1)
    GRASPING = "grasping"  # computed by the grasp model
    SCENE = "scene"  # facts a scene (kitchen, ...) provides
    REASONING = "reasoning"  # computed by the location costmaps' reach reasoning


class Need(Enum):
    """Whether a robot description must provide a predicate."""

    OPTIONAL = "optional"
    ROBOT = "every robot"  # one fact per robot in robot/1
    ARM = "every arm"  # one fact per arm in arm/2


class Answers(Protocol):
    """What typed queries need of a knowledge base."""

    def query(self, text: str, **bindings: Any) -> Iterator[dict[str, Any]]:
        """The answers of ``text`` with named variables bound to Python values."""


Row = TypeVar("Row")


@dataclass(frozen=True)
class Predicate(Generic[Row]):
    """A predicate with its row type (a frozen dataclass, one field per argument).

    Attributes:
        name: the functor (``robot_tool_frame``).
        row: the frozen dataclass its answers come back as.
        source: who provides it.
        meaning: one line, said when it is missing and on the reference page.
        need: whether a description must provide it (description predicates only).
    """

    name: str
    row: type[Row]
    source: Source
    meaning: str
    need: Need = Need.OPTIONAL
    arguments: tuple[Argument, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "arguments", arguments_of(self.row))

    @property
    def arity(self) -> int:
        """The number of arguments."""
        return len(self.arguments)

    @property
    def indicator(self) -> str:
        """``name/arity``, as ``KnowledgeBase.predicates()`` lists it."""
        return f"{self.name}/{self.arity}"

    @cached_property
    def _goal(self) -> str:
        goal = f"{self.name}({', '.join(a.variable for a in self.arguments)})"
        if self.source is Source.WORLD:
            return f"world({self.arguments[0].variable}), {goal}"
        return goal

    @cached_property
    def _variables(self) -> dict[str, str]:
        """Each argument's Prolog variable by its name (typed queries read it per answer)."""
        return {a.name: a.variable for a in self.arguments}

    def _bindings(self, bound: dict[str, Any]) -> dict[str, Any]:
        names = self._variables
        for key in bound:
            if key not in names:
                raise UnknownArgumentError(self.indicator, key, tuple(names))
        return {names[key]: to_prolog(value) for key, value in bound.items()}

    def answers(self, kb: Answers, **bound: object) -> Iterator[Row]:
        """Every answer as a row, arguments bound by name (``robot="pr2"``)."""
        names = self._variables
        for answer in kb.query(self._goal, **self._bindings(bound)):
            yield self.row(
                **{
                    a.name: a.convert(answer.get(names[a.name], bound.get(a.name)))
                    for a in self.arguments
                }
            )

    def first(self, kb: Answers, **bound: object) -> Row | None:
        """The first answer, or None when there is none."""
        return next(self.answers(kb, **bound), None)

    def holds(self, kb: Answers, **bound: object) -> bool:
        """Whether there is an answer."""
        return next(kb.query(self._goal, **self._bindings(bound)), None) is not None

    def fact(self, row: Row) -> Term:
        """The fact that states ``row`` (tuples become Prolog lists)."""
        if not isinstance(row, self.row):
            raise KnowledgeUsageError(f"{self.indicator} states a {self.row.__name__}, not {row!r}")
        return Term(self.name, tuple(to_prolog(getattr(row, a.name)) for a in self.arguments))

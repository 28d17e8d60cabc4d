"""Action tables: action types by name, the table PERFORM runs action designators by.

PERFORM (:func:`~robocram.execution.perform.perform`) runs an action designator whose type
is in its table by a plain Python call to the type's plan (a reader and an IDE follow
``perform(an.action(type="transporting", ...))`` to ``transport``), and grounds any other
designator in the knowledge base. The table is the one given to ``perform(d, actions)``,
else the default: empty here, and :mod:`robocram.plans` makes its own table
(``robocram.plans.ACTIONS``: navigating, searching, transporting, ...) the default when it
is imported. Plans sit above this layer, so the table comes to PERFORM from them; it
holds only which plan a type runs, never world or robot state.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from types import MappingProxyType

from robocram.execution.action_type import ActionType
from robocram.logic import Term


class ActionTableError(ValueError):
    """An action table asked to hold one type twice (a ValueError, as it always was)."""


@dataclass(frozen=True)
class ActionTable:
    """Action types by their ``type``; immutable, extended by :meth:`adding`."""

    types: Mapping[str, ActionType]

    @classmethod
    def of(cls, *types: ActionType) -> ActionTable:
        """A table of ``types``; a type named twice is refused."""
        return cls(MappingProxyType({})).adding(*types)

    def adding(self, *types: ActionType) -> ActionTable:
        """This table with ``types`` added (the one registration of a new action type)."""
        found = dict(self.types)
        for t in types:
            if t.type in found:
                raise ActionTableError(
                    f"action type {t.type!r} is already in the table; give the new one another name"
                )
            found[t.type] = t
        return ActionTable(MappingProxyType(found))

    def __getitem__(self, type_: str) -> ActionType:
        return self.types[type_]

    def __contains__(self, type_: object) -> bool:
        return type_ in self.types

    def __iter__(self) -> Iterator[str]:
        return iter(self.types)

    def facts(self) -> list[Term]:
        """``robocram_action_type(T)`` for every type of the table."""
        return [Term("robocram_action_type", (t,)) for t in self.types]


@dataclass
class _Default:
    """The table PERFORM uses when it is given none (see the module docstring)."""

    table: ActionTable


_DEFAULT = _Default(ActionTable.of())


def default_actions() -> ActionTable:
    """The table PERFORM runs action designators by when it is given none."""
    return _DEFAULT.table


def use_default_actions(table: ActionTable) -> None:
    """Make ``table`` PERFORM's default (:mod:`robocram.plans` does, with its own)."""
    _DEFAULT.table = table

"""One action type of an action table: its keys, the plan that performs it, its result.

An action designator's properties are checked before its plan runs: a key the type does
not know, or a required key left out, raises :class:`DesignatorPropertyError` naming the
key and every valid one, so a typo never silently falls back to a default. What PERFORM
returns for the type is what its plan returns: :attr:`ActionType.result` names that class
(read from the plan's annotation), so a reader of the table knows what to expect.
"""

from __future__ import annotations

import typing
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from robocram.designators import Designator, DesignatorPropertyError


@dataclass(frozen=True)
class ActionType:
    """An action ``type`` (CRAM's word), its required and optional keys, its plan."""

    type: str
    required: tuple[str, ...]
    optional: tuple[str, ...]
    plan: Callable[..., object]

    @property
    def keys(self) -> tuple[str, ...]:
        """Every key the type accepts, sorted (``type`` itself left out)."""
        return tuple(sorted({*self.required, *self.optional}))

    def arguments(self, designator: Designator[object]) -> dict[str, Any]:
        """The plan's keyword arguments from ``designator``'s checked properties."""
        given = {key: value for key, value in designator.properties if key != "type"}
        for key in given:
            if key not in self.keys:
                raise DesignatorPropertyError(
                    f"a {self.type!r} action has no key {key!r}; valid keys: "
                    f"{', '.join(self.keys) or 'none'}",
                    key,
                    designator,
                )
        for key in self.required:
            if key not in given:
                raise DesignatorPropertyError(
                    f"a {self.type!r} action needs the key {key!r}; valid keys: "
                    f"{', '.join(self.keys)}",
                    key,
                    designator,
                )
        return given

    @property
    def result(self) -> object:
        """The class (or type expression) the plan returns, from its annotation; ``object``
        when the plan does not say."""
        try:
            hints = typing.get_type_hints(self.plan)
        except (NameError, TypeError):  # an annotation that does not resolve here
            return object
        found: object = hints.get("return", object)
        return found

    def run(self, designator: Designator[object]) -> Any:
        """Check ``designator`` and run the plan with its properties."""
        return self.plan(**self.arguments(designator))

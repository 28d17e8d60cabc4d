"""One action type of the action table: its keys and the plan that performs it.

An action designator's properties are checked before its plan runs: a key the type does
not know, or a required key left out, raises :class:`DesignatorPropertyError` naming the
key and every valid one, so a typo never silently falls back to a default.
"""

from __future__ import annotations

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

    def perform(self, designator: Designator[object]) -> Any:
        """Check ``designator`` and run the plan with its properties."""
        return self.plan(**self.arguments(designator))

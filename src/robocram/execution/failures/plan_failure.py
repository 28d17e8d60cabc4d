"""The root of all plan failures and the mechanism that keeps its ~40 subclasses short.

A failure class declares the data it carries as typed attributes defaulting to None
(``goal: float | None = None``), a one-line ``summary`` and a ``hint`` saying what to try.
Instances take the fields as keywords; ``str(failure)`` names what happened, the data,
any context added on the way up (process module, command) and the hint. Fields left out
are ``None`` and are not printed. ``fields`` lists a class's fields, inherited ones first.
"""

from __future__ import annotations

import difflib
import re
from typing import Any, ClassVar, Self

from robocram.execution.errors import ExecutionUnknownKey, ExecutionUsageError


def cram_name(class_name: str) -> str:
    """Turn ``TorsoGoalNotReached`` into CRAM's ``torso-goal-not-reached``."""
    return re.sub(r"(?<!^)(?=[A-Z])", "-", class_name).lower()


class PlanFailure(Exception):
    """A plan step did not achieve its goal; handlers may retry or recover."""

    fields: ClassVar[tuple[str, ...]] = ()
    summary: ClassVar[str] = "the plan failed"
    hint: ClassVar[str] = ""
    cram_name: ClassVar[str] = "plan-failure"

    def __init_subclass__(cls, **kwargs: object) -> None:
        super().__init_subclass__(**kwargs)
        own = [
            name
            for name, annotation in cls.__dict__.get("__annotations__", {}).items()
            if "ClassVar" not in str(annotation)
        ]
        cls.fields = tuple(dict.fromkeys(cls.fields + tuple(own)))
        cls.cram_name = cram_name(cls.__name__)

    def __init__(self, message: str | None = None, **data: object) -> None:
        unknown = [key for key in data if key not in self.fields]
        if unknown:
            raise ExecutionUsageError(self._unknown_field_message(unknown[0]))
        self.message = message
        for name in self.fields:
            setattr(self, name, data.get(name))
        self.context: dict[str, object] = {}
        super().__init__(message or self.summary)

    @classmethod
    def _unknown_field_message(cls, key: str) -> str:
        allowed = ", ".join(cls.fields) or "none"
        close = difflib.get_close_matches(key, cls.fields, n=1)
        guess = f"; did you mean {close[0]!r}?" if close else ""
        return f"{cls.__name__} has no field {key!r} (fields: {allowed}){guess}"

    @property
    def data(self) -> dict[str, object]:
        """The fields and their values, in declaration order (inherited first)."""
        return {name: getattr(self, name) for name in self.fields}

    def add_context(self, **context: object) -> Self:
        """Record where the failure passed (e.g. process module and command); returns self."""
        self.context.update(context)
        return self

    def __str__(self) -> str:
        parts = [self.message or self.summary]
        shown = ", ".join(f"{k}={v!r}" for k, v in self.data.items() if v is not None)
        if shown:
            parts.append(f"({shown})")
        if self.context:
            parts.append("[" + ", ".join(f"{k}={v!r}" for k, v in self.context.items()) + "]")
        text = " ".join(parts)
        return f"{text}; {self.hint}" if self.hint else text

    def __reduce__(self) -> tuple[Any, ...]:
        return (_rebuild, (type(self), self.message, self.data, self.context))


def _rebuild(
    cls: type[PlanFailure],
    message: str | None,
    data: dict[str, object],
    context: dict[str, object],
) -> PlanFailure:
    failure = cls(message, **{k: v for k, v in data.items() if v is not None})
    return failure.add_context(**context)


def failure_class(name: str) -> type[PlanFailure]:
    """Find a failure class by CRAM name (``torso-goal-not-reached``) or class name."""
    classes = _all_subclasses(PlanFailure)
    by_name = {c.cram_name: c for c in classes} | {c.__name__: c for c in classes}
    if name in by_name:
        return by_name[name]
    close = difflib.get_close_matches(name, list(by_name), n=1)
    guess = f"; did you mean {close[0]!r}?" if close else ""
    raise ExecutionUnknownKey(f"no plan failure named {name!r}{guess}")


def _all_subclasses(cls: type[PlanFailure]) -> list[type[PlanFailure]]:
    found = [cls]
    for sub in cls.__subclasses__():
        found.extend(_all_subclasses(sub))
    return found

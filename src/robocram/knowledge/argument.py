"""One argument of a predicate: its name, Python type and unit, read off a row dataclass.

A predicate's row is a frozen dataclass whose fields are the predicate's arguments in
order; a field's unit sits in its metadata (:func:`unit`). The converter of a field turns
a Prolog answer (atoms as ``str``, lists as ``list``) into the field's Python type, so a
typed query hands back exactly what the row declares.
"""

from __future__ import annotations

import dataclasses
import typing
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from robocram.knowledge.errors import KnowledgeUsageError
from robocram.logic.convert import to_python
from robocram.logic.terms import make_list
from robocram.logic.value import Value
from robocram.tf import Pose, PoseStamped

JointStates = tuple[tuple[str, float], ...]  # ((joint, value [rad | m]), ...)
Names = tuple[str, ...]
Vector = tuple[float, ...]


def unit(text: str) -> Any:
    """A dataclass field whose value is in ``text`` (``"m"``, ``"rad"``, ``"m | rad"``).

    Answers and facts hold lists as Prolog lists; the converters take both forms.
    """
    return dataclasses.field(metadata={"unit": text})


def _joint_states(value: object) -> JointStates:
    return tuple((str(joint), float(v)) for joint, v in to_python(value))


def _pose_stamped(value: object) -> PoseStamped:
    if not isinstance(value, PoseStamped):
        raise KnowledgeUsageError(f"expected a PoseStamped, got {value!r}")
    return value


_CONVERTERS: dict[object, Callable[[Value], object]] = {
    str: str,
    float: float,
    int: int,
    object: lambda v: v,
    Names: lambda v: tuple(str(x) for x in to_python(v)),
    Vector: lambda v: tuple(float(x) for x in to_python(v)),
    JointStates: _joint_states,
    Pose: Pose.coerce,
    PoseStamped: _pose_stamped,
}
_TYPE_TEXT: dict[object, str] = {
    Names: "list of names",
    Vector: "list of numbers",
    JointStates: "list of [joint, value]",
    object: "any term",
}


def to_prolog(value: object) -> Value:
    """The Prolog form of a row value: plain tuples become lists, the rest stays itself."""
    if type(value) is tuple:  # a Term is a tuple too, and stays a term
        return make_list([to_prolog(v) for v in value])
    return value


@dataclass(frozen=True)
class Argument:
    """A predicate argument: ``name`` (the row field), Python ``type`` and ``unit``."""

    name: str
    type: object
    unit: str
    convert: Callable[[Value], object]

    @cached_property  # read for every answer of a typed query
    def variable(self) -> str:
        """The Prolog variable a query uses for it: ``joint_states`` -> ``JointStates``."""
        return "".join(part.capitalize() for part in self.name.split("_"))

    @property
    def type_text(self) -> str:
        """The type in words, for the reference page."""
        return _TYPE_TEXT.get(self.type, getattr(self.type, "__name__", str(self.type)))


def arguments_of(row: type) -> tuple[Argument, ...]:
    """The arguments a row dataclass declares, in order; every field type needs a converter."""
    hints = typing.get_type_hints(row)
    found = []
    for f in dataclasses.fields(row):
        kind = hints[f.name]
        if kind not in _CONVERTERS:
            raise KnowledgeUsageError(f"{row.__name__}.{f.name}: no converter for {kind!r}")
        found.append(Argument(f.name, kind, f.metadata.get("unit", ""), _CONVERTERS[kind]))
    return tuple(found)

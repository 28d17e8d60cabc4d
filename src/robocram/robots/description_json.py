"""A robot description as JSON text: the data a trace keeps to build the robot again.

A description read from a file is only as durable as the file: moved, edited or left on
another machine, the run's robot is lost. Its values are plain data (names, joint values,
poses, nested frozen dataclasses), so they are written out field by field and read back by
the fields' declared types. Data, not code: nothing of a stored description is executed.
The model is not part of it: the trace keeps the model's URDF text on its own.
"""

from __future__ import annotations

import dataclasses
import json
import types
from collections.abc import Mapping
from pathlib import Path
from typing import Literal, TypeVar, Union, get_args, get_origin, get_type_hints

from robocram.robots.description import RobotDescription
from robocram.robots.errors import DescriptionError
from robocram.robots.robot_model import RobotModel

T = TypeVar("T")
NOT_RECORDED = frozenset({"model", "source"})  # the model is kept as URDF; source is the file


class DescriptionRecordError(DescriptionError):
    """A stored description does not read back: a field of an unknown type or a bad value."""


def description_to_json(desc: RobotDescription) -> str:
    """``desc``'s fields as JSON (of :class:`RobotDescription`; a loaded one's values as loaded)."""
    values = {
        f.name: _encoded(getattr(desc, f.name), f.name)
        for f in dataclasses.fields(RobotDescription)
        if f.name not in NOT_RECORDED
    }
    return json.dumps(values, sort_keys=True)


def description_from_json(
    text: str, model: RobotModel | None = None, source: str = ""
) -> RobotDescription:
    """The description ``text`` (from :func:`description_to_json`) holds, with ``model``.

    Raises:
        DescriptionRecordError: the text is not a stored description, or a value does not
            have its field's type (a trace written by a robocram whose fields differ).
    """
    try:
        values = json.loads(text)
    except json.JSONDecodeError as err:
        raise DescriptionRecordError(f"a stored description is not JSON ({err})") from err
    if not isinstance(values, dict):
        raise DescriptionRecordError("a stored description is not a JSON object")
    decoded = _decoded(RobotDescription, values, "description")
    if not isinstance(decoded, RobotDescription):
        raise DescriptionRecordError("a stored description does not read as a description")
    return dataclasses.replace(decoded, model=model, source=source)


def _encoded(value: object, where: str) -> object:
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {
            f.name: _encoded(getattr(value, f.name), f"{where}.{f.name}")
            for f in dataclasses.fields(value)
            if f.name not in NOT_RECORDED and f.name != "findings"
        }
    if isinstance(value, Path):
        return str(value)
    if isinstance(value, (tuple, list)):
        return [_encoded(v, f"{where}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, Mapping):
        return {str(k): _encoded(v, f"{where}[{k!r}]") for k, v in value.items()}
    if value is None or isinstance(value, (str, int, float, bool)):
        return value
    raise DescriptionRecordError(
        f"{where} holds a {type(value).__name__}, which a trace cannot keep as data; "
        "give the field a plain value (numbers, names, poses)"
    )


def _decoded(hint: object, value: object, where: str) -> object:
    """``value`` read as type ``hint`` (a field's declared type)."""
    origin = get_origin(hint)
    if origin in (Union, types.UnionType):
        return _decoded_union(get_args(hint), value, where)
    if origin is Literal or hint in (str, int, bool):
        return value
    if hint is float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise DescriptionRecordError(f"{where}: {value!r} is not a number")
        return float(value)
    if hint is Path:
        return Path(str(_checked(value, str, where)))
    if origin is tuple:
        return _decoded_tuple(get_args(hint), value, where)
    if origin is Mapping or origin is dict:
        _, item = get_args(hint)
        items = _checked(value, dict, where)
        return {k: _decoded(item, v, f"{where}[{k!r}]") for k, v in items.items()}
    if isinstance(hint, type) and dataclasses.is_dataclass(hint):
        return _decoded_dataclass(hint, value, where)
    raise DescriptionRecordError(f"{where}: no reading for a field of type {hint}")


def _decoded_union(arms: tuple[object, ...], value: object, where: str) -> object:
    if value is None and type(None) in arms:
        return None
    kinds = [arm for arm in arms if arm is not type(None)]
    if str in kinds and isinstance(value, str):
        return value  # ``str | Path`` keeps the text as written
    if len(kinds) == 1:
        return _decoded(kinds[0], value, where)
    raise DescriptionRecordError(f"{where}: {value!r} is none of {kinds}")


def _decoded_tuple(args: tuple[object, ...], value: object, where: str) -> tuple[object, ...]:
    items = _checked(value, list, where)
    if len(args) == 2 and args[1] is Ellipsis:
        return tuple(_decoded(args[0], v, f"{where}[{i}]") for i, v in enumerate(items))
    if len(args) != len(items):
        raise DescriptionRecordError(f"{where}: {len(items)} values where {len(args)} belong")
    return tuple(
        _decoded(a, v, f"{where}[{i}]") for i, (a, v) in enumerate(zip(args, items, strict=True))
    )


def _decoded_dataclass(cls: type, value: object, where: str) -> object:
    values = _checked(value, dict, where)
    hints = get_type_hints(cls)  # the class's module resolves its annotations
    known = {f.name for f in dataclasses.fields(cls)}
    unknown = sorted(set(values) - known)
    if unknown:
        raise DescriptionRecordError(
            f"{where}: no field {unknown[0]!r} in {cls.__name__} (written by another "
            "robocram); give the description file (--robot-file FILE.py)"
        )
    fields = {k: _decoded(hints[k], v, f"{where}.{k}") for k, v in values.items()}
    try:
        return cls(**fields)
    except (TypeError, ValueError) as err:
        raise DescriptionRecordError(f"{where}: {err}") from err


def _checked(value: object, kind: type[T], where: str) -> T:
    if not isinstance(value, kind):
        raise DescriptionRecordError(f"{where}: {value!r} is not a {kind.__name__}")
    return value

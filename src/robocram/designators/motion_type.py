"""One motion type as data: its properties, groundings, process module and plausible answer.

A :class:`MotionType` is the single place a motion is described. From it come the
``motion_grounding/2`` rules (:func:`grounding_rules`), the property checks of motion
designators (:func:`check_property_types`, :func:`missing_property_error`), the
``matching_process_module/2`` facts of an environment (by ``resource``) and the dispatch
of process modules (by ``Command``), so a process module of any environment (projection,
recording, ROS) handles exactly the commands the table lists for its resource.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from enum import Enum
from typing import TYPE_CHECKING

from robocram.designators.errors import MotionPropertyError
from robocram.logic import name_atom

if TYPE_CHECKING:
    from robocram.designators.designator import Designator


class Answer(Enum):
    """What a process module that only records commands plausibly answers."""

    GOAL = "goal"  # the command's goal arguments (one value, or a tuple of them)
    JOINTS = "joints"  # the joint values set (and remembered as the robot's state)
    GRIPPER = "gripper"  # the gripper action; gripping answers the object detected last
    PERCEIVED = "perceived"  # a designator for the object asked for, with its known pose
    NO_RANGE = "no_range"  # infinity: nothing to measure without a world


@dataclass(frozen=True)
class Atom:
    """A constant atom in a command, e.g. ``open`` in ``move_gripper_joint(G, open, E)``."""

    name: str


@dataclass(frozen=True)
class MotionProperty:
    """One property a motion designator may carry.

    Attributes:
        key: the property key (``joint_angle``).
        types: the accepted Python types of its value.
        expected: the accepted types in words, for error messages.
        default: the atom a command gets when the property is absent; None makes the
            property required by every grounding that uses it.
        target: resolve the value through ``common_target_pose/2`` (a location designator
            gives one command per solution, a pose gives itself).
    """

    key: str
    types: tuple[type, ...]
    expected: str
    default: str | None = None
    target: bool = False


@dataclass(frozen=True)
class Command:
    """One grounding of a motion type: the command term and what it is built from.

    Attributes:
        name: the command's functor (``move_tcp``).
        args: per argument, a property key or a constant :class:`Atom`.
        goal: indices of the arguments a recorder answers with (``Answer.GOAL``).
        unless_all: the grounding does not apply when all these properties are present
            (the one-arm form of a motion yields to its two-arm form).
    """

    name: str
    args: tuple[str | Atom, ...]
    goal: tuple[int, ...] = (0,)
    unless_all: tuple[str, ...] = ()

    @property
    def arity(self) -> int:
        """The number of arguments of the command term."""
        return len(self.args)

    @property
    def uses(self) -> tuple[str, ...]:
        """The property keys this grounding reads."""
        return tuple(a for a in self.args if isinstance(a, str))


@dataclass(frozen=True)
class MotionType:
    """A motion type: its designator vocabulary and where its commands go.

    Attributes:
        type: the designator's ``type`` property (``moving-tcp``).
        properties: every property the groundings read.
        commands: the groundings, tried in order (each may give several solutions).
        resource: the process module resource executing the commands (``arms``); an
            environment names its module ``<prefix>_<resource>``.
        answer: what a recording process module answers.
        family: the fact group family: ``common`` motions every robot understands,
            ``flying`` motions only flying robots do.
    """

    type: str
    properties: tuple[MotionProperty, ...]
    commands: tuple[Command, ...]
    resource: str
    answer: Answer
    family: str = "common"

    def prop(self, key: str) -> MotionProperty:
        """The property ``key`` of this motion type."""
        return next(p for p in self.properties if p.key == key)

    def required(self, command: Command) -> tuple[MotionProperty, ...]:
        """The properties ``command`` needs present (those without a default)."""
        return tuple(p for p in map(self.prop, command.uses) if p.default is None)


def _error(
    motion: MotionType,
    prop: MotionProperty,
    designator: Designator,
    why: str,
    grounded_types: tuple[str, ...] = (),
) -> MotionPropertyError:
    return MotionPropertyError(
        why,
        motion=motion.type,
        key=prop.key,
        expected=prop.expected,
        designator=designator,
        grounded_types=grounded_types,
    )


def check_property_types(motion: MotionType, designator: Designator) -> None:
    """Raise :class:`MotionPropertyError` for a property of ``designator`` of the wrong type."""
    for prop in motion.properties:
        for value in designator.get_all(prop.key):
            if not isinstance(value, prop.types) or isinstance(value, bool):
                why = (
                    f"motion {motion.type!r} needs property {prop.key!r} to be "
                    f"{prop.expected}, got {value!r} in {designator.description}"
                )
                raise _error(motion, prop, designator, why)


def check_known_keys(motion: MotionType, designator: Designator) -> None:
    """Raise :class:`MotionPropertyError` for a key no grounding reads (``efort``).

    Called once a grounding matched: a misspelt optional property would otherwise be
    ignored silently. (Without a match the missing property is the better message.)
    """
    known = sorted({"type", *(p.key for p in motion.properties)})
    for key, _ in designator.properties:
        if key in known:
            continue
        close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
        hint = f"did you mean {close[0]!r}? " if close else ""
        raise MotionPropertyError(
            f"motion {motion.type!r} has no property {key!r} in {designator.description}; "
            f"{hint}it takes {', '.join(map(repr, known))}",
            motion=motion.type,
            key=key,
            expected="one of " + ", ".join(known),
            designator=designator,
        )


def missing_property_error(
    motion: MotionType, designator: Designator, grounded_types: tuple[str, ...] = ()
) -> MotionPropertyError | None:
    """The error naming the property ``designator`` lacks, or None when none is missing.

    A property is missing when no grounding of the motion type finds all the properties
    it requires.
    """
    present = {k for k, _ in designator.properties}
    options = list(dict.fromkeys(motion.required(c) for c in motion.commands))
    if not options or any(all(p.key in present for p in needed) for needed in options):
        return None
    first = next(p for p in options[0] if p.key not in present)
    alternatives = " or ".join("+".join(p.key for p in needed) for needed in options)
    why = (
        f"the rules for type {motion.type!r} did not match {designator.description}: "
        f"it needs property {first.key!r} ({first.expected}); the motion takes "
        f"{alternatives}; types with motion_grounding rules: {list(grounded_types)}"
    )
    return _error(motion, first, designator, why, grounded_types)


def _var(key: str, suffix: str = "") -> str:
    return "".join(part.capitalize() for part in key.split("_")) + suffix


def _rule(motion: MotionType, command: Command, table: str) -> str:
    args: list[str] = []
    reads: list[str] = []
    resolves: list[str] = []
    for arg in command.args:
        if isinstance(arg, Atom):
            args.append(name_atom(arg.name))
            continue
        prop = motion.prop(arg)
        value = _var(arg, "Value") if prop.target else _var(arg)
        args.append(_var(arg))
        if prop.default is not None:
            resolves.append(
                f"common_prop_or_default(D, {arg}, {name_atom(prop.default)}, {_var(arg)})"
            )
            continue
        reads.append(f"desig_prop(D, {arg}, {value})")
        if prop.target:
            resolves.append(f"common_target_pose({value}, {_var(arg)})")
    body = [*reads]
    if command.unless_all:  # after the reads, so other forms fail before testing it
        both = ", ".join(f"desig_prop(D, {key}, _)" for key in command.unless_all)
        body.append(f"\\+ ({both})")
    body.extend(resolves)
    head = f"{table}({name_atom(motion.type)}, D, {command.name}({', '.join(args)}))"
    return head + (" :-\n    " + ",\n    ".join(body) if body else "") + "."


def grounding_rules(
    motions: Iterator[MotionType] | tuple[MotionType, ...], table: str = "motion_grounding_by_type"
) -> str:
    """The ``motion_grounding/2`` rules of ``motions`` as Prolog text, in table order.

    One rule reads the designator's ``type`` once and goes on in ``table/3``, whose
    clauses (one per command, in table order) are indexed on the type: a rule per
    command read the type in every rule, ~40 Python calls to ground a ``moving-tcp``.
    ``grounded_motion_type/1`` lists the types, for error messages.
    """
    motions = tuple(motions)
    dispatch = (
        "motion_grounding(D, G) :-\n"
        f"    motion_desig(D),\n    desig_prop(D, type, T),\n    {table}(T, D, G).\n"
    )
    rules = "\n".join(_rule(m, c, table) for m in motions for c in m.commands)
    types = "".join(f"grounded_motion_type({name_atom(m.type)}).\n" for m in motions if m.commands)
    return dispatch + rules + "\n" + types


def commands_of(motions: Mapping[str, MotionType], resource: str) -> dict[tuple[str, int], Command]:
    """The commands a process module of ``resource`` executes, keyed by ``(name, arity)``."""
    return {
        (c.name, c.arity): c for m in motions.values() if m.resource == resource for c in m.commands
    }

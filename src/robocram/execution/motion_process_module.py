"""Process modules driven by the motion table: one per resource, dispatching table commands.

A :class:`MotionProcessModule` owns one ``resource`` of the motion table (``arms``,
``navigation``...). It executes exactly the commands the table grounds for that resource
and dispatches each to its method of the same name (``move_tcp(arm, pose, mode)``);
a subclass missing a method for one of its commands fails when the class is defined.
:func:`matching_facts` writes the ``matching_process_module/2`` and
``available_process_module/1`` facts sending each motion type to the module of its
resource. Any environment (projection, recording, ROS) builds on these two.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from functools import cached_property
from typing import Any

from robocram.designators import MOTION_TYPES, Command, MotionType, commands_of
from robocram.execution.errors import ExecutionUsageError
from robocram.execution.process_module import ProcessModule
from robocram.logic import Term, name_atom


def module_atom(prefix: str, resource: str) -> str:
    """The name of the module of ``resource`` in an environment: ``projection_arms``."""
    return f"{prefix}_{resource}"


def motion_types_of(
    resource: str, motions: Mapping[str, MotionType] = MOTION_TYPES
) -> tuple[str, ...]:
    """The motion types whose commands the module of ``resource`` executes."""
    return tuple(m.type for m in motions.values() if m.resource == resource)


def matching_facts(
    prefix: str, resources: Iterable[str], motions: Mapping[str, MotionType] = MOTION_TYPES
) -> str:
    """Prolog facts sending each motion type to its resource's module, marking it available.

    One rule reads the designator's ``type`` once and finds its modules in the
    ``motion_process_module/3`` table (indexed on the type); a rule per motion type read
    the type once per rule, 14 Python calls per PERFORM on a PR2.
    """
    lines = [
        "matching_process_module(D, PM) :-"
        f" desig_prop(D, type, T), motion_process_module(T, {name_atom(prefix)}, PM)."
    ]
    for resource in resources:
        pm = name_atom(module_atom(prefix, resource))
        for motion in motion_types_of(resource, motions):
            lines.append(f"motion_process_module({name_atom(motion)}, {name_atom(prefix)}, {pm}).")
        lines.append(f"available_process_module({pm}).")
    return "\n".join(lines) + "\n"


class MotionProcessModule(ProcessModule):
    """A process module executing the table's commands of one ``resource``.

    Subclasses set ``resource`` (and ``name``) and define one method per command, named
    after it; or override :meth:`run_command` to handle every command alike.
    """

    resource: str = ""  # a class attribute; an instance may set its own before __init__

    def __init_subclass__(cls, **kwargs: object) -> None:
        super().__init_subclass__(**kwargs)
        if not cls.resource or "run_command" in cls.__dict__:
            return
        missing = sorted(
            {c.name for c in commands_of(MOTION_TYPES, cls.resource).values()}
            - {n for n in dir(cls) if callable(getattr(cls, n, None))}
        )
        if missing:
            raise ExecutionUsageError(
                f"{cls.__name__} executes the {cls.resource!r} commands of the motion table "
                f"but has no method for {missing}; define one per command"
            )

    @cached_property
    def commands(self) -> dict[tuple[str, int], Command]:
        """The commands this module executes, keyed by ``(name, arity)`` (built once)."""
        return commands_of(MOTION_TYPES, self.resource)

    def execute(self, command: object) -> Any:
        """Run a table command of this module's resource (anything else is refused)."""
        table = self.commands
        spec = table.get((command.name, command.arity)) if isinstance(command, Term) else None
        if spec is None or not isinstance(command, Term):
            raise self.unsupported(command, [f"{n}/{a}" for n, a in table])
        return self.run_command(spec, command)

    def run_command(self, spec: Command, command: Term) -> Any:
        """Run ``command`` (described by ``spec``): call the method named after it."""
        method = getattr(self, spec.name)
        return method(*command.args)

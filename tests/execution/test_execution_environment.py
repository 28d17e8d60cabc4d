"""Environments switch knowledge base, resolver, variables and modules for a block."""

from __future__ import annotations

import contextvars
from typing import Any

import pytest

from robocram.designators import LocationResolver, a, bound_kb, current_location_resolver
from robocram.execution import run_top_level
from robocram.execution.environment import Environment
from robocram.execution.perform import perform
from robocram.execution.process_module import ProcessModule
from robocram.execution.process_module_matching import running_process_modules
from robocram.logic import Term, current_kb

SPEED: contextvars.ContextVar[float] = contextvars.ContextVar("speed", default=1.0)


class EchoPM(ProcessModule):
    name = "echo"

    def execute(self, command: Any) -> Any:
        return (command, SPEED.get())


FACTS = """
motion_grounding(D, echo(T)) :- desig_prop(D, type, echoing), desig_prop(D, text, T).
matching_process_module(D, echo) :- desig_prop(D, type, echoing).
available_process_module(echo).
"""


def test_entering_binds_everything_and_leaving_undoes_it() -> None:
    resolver = LocationResolver().with_generator("here", lambda d: ["here"])
    pm = EchoPM()
    env = Environment("echo", [pm], FACTS, location_resolver=resolver, variables={SPEED: 2.5})
    assert bound_kb() is None
    with env as entered:
        assert entered is env and current_kb() is env.kb
        assert current_location_resolver() is resolver and SPEED.get() == 2.5
        assert running_process_modules() == (pm,) and pm.running
        result = run_top_level(lambda: perform(a.motion(type="echoing", text="hi")))
    assert result == (Term("echo", ("hi",)), 2.5)
    assert bound_kb() is None and SPEED.get() == 1.0 and not pm.running
    assert running_process_modules() == ()


def test_the_same_designator_grounds_per_environment() -> None:
    loud = Environment("loud", [EchoPM()], FACTS.replace("echo(T)", "shout(T)"))
    calm = Environment("calm", [EchoPM()], FACTS)
    motion = a.motion(type="echoing", text="hi")
    with loud:
        assert run_top_level(lambda: perform(motion))[0] == Term("shout", ("hi",))
    with calm:
        assert run_top_level(lambda: perform(motion))[0] == Term("echo", ("hi",))


def test_module_lookup_names_the_known_modules() -> None:
    env = Environment("echo", [EchoPM()], FACTS)
    assert env.module("echo").name == "echo"
    with pytest.raises(KeyError, match="has no process module 'base'; it has \\['echo'\\]"):
        env.module("base")

"""PERFORM: grounding, matching process modules, failures, plans and concurrency."""

from __future__ import annotations

import contextvars
from typing import Any

import pytest

from robocram.designators import a, an, install_common_motions
from robocram.execution import PlanFailure, TopLevel, par, pursue, sleep
from robocram.execution.failures import (
    DesignatorFailure,
    DesignatorReferenceFailure,
    NoMatchingProcessModule,
    NotInTopLevel,
    TorsoGoalNotReached,
)
from robocram.execution.perform import perform, register_plan
from robocram.execution.process_module import ProcessModule
from robocram.execution.process_module_matching import (
    install_process_module_interface,
    process_modules_running,
)
from robocram.execution.top_level import run_top_level
from robocram.logic import KnowledgeBase, Term, using_kb

FACTS = """
matching_process_module(D, torso) :- desig_prop(D, type, 'moving-torso').
matching_process_module(D, spare_torso) :- desig_prop(D, type, 'moving-torso').
available_process_module(torso).
available_process_module(spare_torso).
"""


class TorsoPM(ProcessModule):
    name = "torso"
    limit = 0.3

    def __init__(self, hold: float = 0.0) -> None:
        super().__init__()
        self.hold = hold
        self.commands: list[Term] = []

    def execute(self, command: Any) -> Any:
        if self.hold:
            sleep(self.hold)
        (angle,) = command.args
        if angle > self.limit:
            raise TorsoGoalNotReached(goal=angle, reached=self.limit)
        self.commands.append(command)
        return angle


class SpareTorsoPM(TorsoPM):
    name = "spare_torso"
    limit = 1.0


@pytest.fixture
def kb() -> KnowledgeBase:
    kb = install_common_motions(KnowledgeBase())
    install_process_module_interface(kb)
    kb.consult(FACTS, group="torso_facts")
    return kb


def torso(angle: float) -> Any:
    return a.motion(type="moving-torso", joint_angle=angle)


def test_motion_goes_to_the_matching_running_module(kb: KnowledgeBase) -> None:
    pm = TorsoPM()
    with using_kb(kb), process_modules_running(pm):
        tl = TopLevel("top-level")
        value, tree = tl.run(lambda: perform(torso(0.2))), tl.tree
    assert value == 0.2 and pm.commands == [Term("move_torso", (0.2,))]
    assert "perform moving-torso" in tree.render()


def test_no_running_module_is_a_typed_failure_naming_the_designator(kb: KnowledgeBase) -> None:
    with using_kb(kb), pytest.raises(NoMatchingProcessModule) as caught:
        run_top_level(lambda: perform(torso(0.1)))
    assert "(a motion (type moving-torso) (joint_angle 0.1))" in str(caught.value)
    assert caught.value.running == []


def test_first_failure_tries_the_next_module(kb: KnowledgeBase) -> None:
    main, spare = TorsoPM(), SpareTorsoPM()
    with using_kb(kb), process_modules_running(main, spare):
        assert run_top_level(lambda: perform(torso(0.5))) == 0.5
        assert spare.commands == [Term("move_torso", (0.5,))] and main.commands == []
        with pytest.raises(TorsoGoalNotReached) as caught:
            run_top_level(lambda: perform(torso(2.0)))
    assert caught.value.reached == 0.3  # the first module's failure, named
    assert caught.value.context["process_module"] == "torso"


def test_ungroundable_designator_is_a_reference_failure(kb: KnowledgeBase) -> None:
    with (
        using_kb(kb),
        pytest.raises(DesignatorReferenceFailure, match="types with motion_grounding"),
    ):
        run_top_level(lambda: perform(a.motion(type="moving-torso", angle=0.1)))


def test_perform_refuses_locations_and_needs_a_top_level(kb: KnowledgeBase) -> None:
    with using_kb(kb), pytest.raises(DesignatorFailure, match="motion or action designators"):
        run_top_level(lambda: perform(a.location(pose=(0, 0, 0))))  # type: ignore[arg-type]
    with using_kb(kb), pytest.raises(NotInTopLevel):
        perform(torso(0.1))


def test_action_runs_its_registered_plan(kb: KnowledgeBase) -> None:
    def lift_twice(first: float, second: float) -> list[Any]:
        return [perform(torso(first)), perform(torso(second))]

    register_plan(kb, "lift_twice", lift_twice)
    kb.consult(
        "action_grounding(D, lift_twice(0.1, H)) :- desig_prop(D, type, lifting),"
        " desig_prop(D, height, H).",
        group="lifting",
    )
    pm = TorsoPM()
    with using_kb(kb), process_modules_running(pm):
        tl = TopLevel("top-level")
        value, tree = tl.run(lambda: perform(an.action(type="lifting", height=0.25))), tl.tree
    assert value == [0.1, 0.25]
    assert tree.render().count("perform moving-torso") == 2


def test_action_grounded_to_an_unregistered_plan_says_so(kb: KnowledgeBase) -> None:
    register_plan(kb, "known", lambda: None)
    kb.consult("action_grounding(D, juggle(3)) :- desig_prop(D, type, juggling).", group="j")
    with using_kb(kb), pytest.raises(DesignatorReferenceFailure, match="registered: \\['known'\\]"):
        run_top_level(lambda: perform(an.action(type="juggling")))


def test_many_parallel_performs_none_lost_none_doubled(kb: KnowledgeBase) -> None:
    pm = TorsoPM()
    angles = [i / 1000 for i in range(40)]
    with using_kb(kb), process_modules_running(pm):
        values = run_top_level(lambda: par(*[(lambda x=x: perform(torso(x))) for x in angles]))
    assert values == angles
    assert sorted(c.args[0] for c in pm.commands) == angles and pm.executed == 40


def test_cancelled_performs_leave_nothing_running(kb: KnowledgeBase) -> None:
    pm = TorsoPM(hold=5.0)
    with using_kb(kb), process_modules_running(pm):
        run_top_level(
            lambda: pursue(
                lambda: sleep(0.05),
                lambda: perform(torso(0.1)),
                lambda: perform(torso(0.2)),
            )
        )
        assert not pm.busy and pm.waiting == 0 and pm.commands == []
    assert not pm.running


def test_process_modules_are_shared_by_nested_blocks(kb: KnowledgeBase) -> None:
    pm = TorsoPM()
    with process_modules_running(pm) as outer:
        with process_modules_running(pm) as inner:
            assert outer == inner == (pm,)
        assert pm.running
        impostor = type("Other", (TorsoPM,), {})()
        with pytest.raises(ValueError, match="already taken"), process_modules_running(impostor):
            pass
    assert not pm.running


def test_failures_are_plan_failures_for_handlers(kb: KnowledgeBase) -> None:
    var: contextvars.ContextVar[int] = contextvars.ContextVar("unused", default=0)
    with using_kb(kb), process_modules_running(TorsoPM()), pytest.raises(PlanFailure):
        run_top_level(lambda: perform(torso(0.9)))
    assert var.get() == 0

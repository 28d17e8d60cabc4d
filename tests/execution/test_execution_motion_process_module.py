"""Process modules driven by the motion table, and the facts choosing them (no physics)."""

from __future__ import annotations

import pytest

from robocram.designators import a, install_common_motions
from robocram.execution import (
    Environment,
    MotionProcessModule,
    matching_facts,
    motion_types_of,
    perform,
    top_level,
)
from robocram.execution.failures import ProcessModuleFailure
from robocram.logic import KnowledgeBase, Term


class TorsoLog(MotionProcessModule):
    """A torso that remembers its height [m]."""

    name = "log_torso"
    resource = "torso"

    def __init__(self) -> None:
        super().__init__()
        self.height = 0.0

    def move_torso(self, value: float) -> float:
        self.height = value
        return value


def test_a_module_missing_a_command_of_its_resource_fails_at_definition() -> None:
    with pytest.raises(TypeError, match=r"no method for \['inspect'\]"):

        class HalfCamera(MotionProcessModule):
            name = "half_camera"
            resource = "perception"

            def detect(self, desig: object) -> object:
                return desig


def test_a_module_refuses_commands_of_other_resources() -> None:
    pm = TorsoLog()
    pm.start()
    try:
        assert pm.call(Term("move_torso", (0.2,))) == 0.2
        with pytest.raises(ProcessModuleFailure, match=r"it handles \['move_torso/1'\]"):
            pm.call(Term("move_base", ((0, 0, 0),)))
    finally:
        pm.stop()


def test_matching_facts_send_each_table_type_to_its_resource_module() -> None:
    assert motion_types_of("grippers") == (
        "opening",
        "closing",
        "gripping",
        "moving-gripper-joint",
    )
    facts = matching_facts("log", ["torso"])
    assert facts == (
        "matching_process_module(D, PM) :- desig_prop(D, type, T), "
        "motion_process_module(T, log, PM).\n"
        "motion_process_module('moving-torso', log, log_torso).\n"
        "available_process_module(log_torso).\n"
    )


def test_two_environments_of_one_prefix_share_a_knowledge_base() -> None:
    kb = install_common_motions(KnowledgeBase())
    Environment("one", [], facts=matching_facts("log", ["torso"]), kb=kb)
    Environment("two", [], facts=matching_facts("log", ["torso", "grippers"]), kb=kb)
    d = a.motion(type="opening", gripper="left")
    answers = [ans["PM"] for ans in kb.query("matching_process_module(D, PM)", D=d)]
    assert answers == ["log_grippers", "log_grippers"]


def test_an_environment_of_table_modules_performs_motions_without_projection() -> None:
    pm = TorsoLog()
    kb = install_common_motions(KnowledgeBase())
    env = Environment("log", [pm], facts=matching_facts("log", ["torso"]), kb=kb)
    with env, top_level():
        assert perform(a.motion(type="moving-torso", joint_angle=0.25)) == 0.25
    assert pm.height == 0.25

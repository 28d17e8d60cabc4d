"""The motion table: groundings generated from it, property checks, its vocabulary."""

from __future__ import annotations

import typing

import pytest

from robocram.designators import (
    MOTION_TYPES,
    Atom,
    GroundingError,
    MotionPropertyError,
    MotionType,
    a,
    an,
    commands_of,
    install_common_motions,
    install_motion_family,
    motion_types,
)
from robocram.logic import KnowledgeBase, Term

SAMPLES: dict[str, object] = {
    "target": (1.0, 0.0, 1.0),
    "left_target": (1.0, 0.5, 1.0),
    "right_target": (1.0, -0.5, 1.0),
    "joint_angle": 0.2,
    "frame": "r_gripper",
    "direction": (1.0, 0.0, 0.0),
    "gripper": "left",
    "arm": "right",
    "configuration": [["j1", 0.1]],
    "left_configuration": [["l1", 0.1]],
    "right_configuration": [["r1", 0.2]],
    "part": "kitchen",
    "joint": "drawer_1_joint",
    "handle": "drawer_1_handle",
    "path": [(1.0, 0.0, 1.0), (1.1, 0.0, 1.0)],
    "tool": "knife-1",
    "source": "cup-1",
    "destination": "bowl-1",
    "amount": 50.0,
    "item": "bread-1",
    "cuts": [0.0],
    "depth": 0.25,
}


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    return install_motion_family(install_motion_family(KnowledgeBase(), "flying"), "legged")


def _cases() -> list[tuple[MotionType, int]]:
    return [(m, i) for m in MOTION_TYPES.values() for i in range(len(m.commands))]


@pytest.mark.parametrize(("motion", "index"), _cases(), ids=lambda v: getattr(v, "type", v))
def test_every_table_command_is_grounded_from_its_required_properties(
    kb: KnowledgeBase, motion: MotionType, index: int
) -> None:
    command = motion.commands[index]
    props = {p.key: SAMPLES.get(p.key, an.object(type="cup")) for p in motion.required(command)}
    grounded = a.motion(type=motion.type, **props).reference(kb)
    expected = tuple(
        arg.name if isinstance(arg, Atom) else props.get(arg, motion.prop(arg).default)
        for arg in command.args
    )
    assert grounded == Term(command.name, expected)


def test_the_table_has_one_entry_per_type_and_flying_is_its_own_family() -> None:
    assert [m.type for m in motion_types("flying")] == ["flying", "distance-sensing"]
    assert [m.type for m in motion_types("legged")] == ["crouching"]
    assert len(motion_types()) == len(MOTION_TYPES) == 18
    assert set(commands_of(MOTION_TYPES, "arms")) == {
        ("move_tcp", 4),
        ("move_tcp_both", 3),
        ("move_joints", 4),
        ("move_joints_both", 3),
        ("move_part", 5),
    }
    assert set(commands_of(MOTION_TYPES, "perception")) == {("detect", 1), ("inspect", 1)}


def test_flying_motions_are_only_in_a_kb_that_installs_them() -> None:
    kb = install_common_motions(KnowledgeBase())
    with pytest.raises(GroundingError, match="no motion_grounding rule knows type 'flying'"):
        a.motion(type="flying", target=(0, 0, 1)).reference(kb)


def test_a_wrongly_typed_property_names_motion_property_and_type(kb: KnowledgeBase) -> None:
    with pytest.raises(MotionPropertyError) as caught:
        a.motion(type="moving-torso", joint_angle="high").reference(kb)
    error = caught.value
    assert (error.motion, error.key, error.expected) == (
        "moving-torso",
        "joint_angle",
        "a number [m | rad]",
    )
    assert "got 'high'" in str(error)
    with pytest.raises(MotionPropertyError, match="'object' to be an object designator"):
        a.motion(type="inspecting", object="mug").reference(kb)


def test_a_missing_property_names_it_and_the_alternatives(kb: KnowledgeBase) -> None:
    with pytest.raises(MotionPropertyError) as caught:
        a.motion(type="moving-tcp", arm="left", collision_mode="allow_all").reference(kb)
    error = caught.value
    assert (error.motion, error.key) == ("moving-tcp", "left_target")
    assert "left_target+right_target or left_target or right_target or arm+target" in str(error)
    assert "moving-tcp" in error.grounded_types


def test_a_user_type_outside_the_table_is_not_checked() -> None:
    kb = install_common_motions(KnowledgeBase())
    kb.consult(
        "motion_grounding(D, wave(H)) :- desig_prop(D, type, waving), desig_prop(D, hand, H).",
        group="waving",
    )
    assert a.motion(type="waving", hand=3).reference(kb) == Term("wave", (3,))


def test_designators_are_generic_over_what_they_resolve_to() -> None:
    from robocram.designators import ActionDesignator, MotionDesignator

    assert typing.get_args(MotionDesignator.__orig_bases__[0]) == (Term,)  # type: ignore[attr-defined]
    assert typing.get_args(ActionDesignator.__orig_bases__[0]) == (object,)  # type: ignore[attr-defined]

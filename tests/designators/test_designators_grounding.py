"""Prolog access to designators and the common motion groundings."""

from __future__ import annotations

import pytest

from robocram.designators import (
    GroundingError,
    Kind,
    LocationResolver,
    a,
    an,
    grounded_types,
    install_common_motions,
    install_designator_predicates,
    using_location_resolver,
)
from robocram.logic import KnowledgeBase, Term, using_kb


@pytest.fixture
def kb() -> KnowledgeBase:
    return install_common_motions(KnowledgeBase())


def test_desig_prop_enumerates_and_tests_properties(kb: KnowledgeBase) -> None:
    d = a.motion(type="moving-torso", joint_angle=0.2)
    pairs = [(s["K"], s["V"]) for s in kb.query("desig_prop(D, K, V)", D=d)]
    assert pairs == [("type", "moving-torso"), ("joint_angle", 0.2)]
    assert kb.holds("desig_prop(D, type, 'moving-torso')", D=d)
    assert not kb.holds("desig_prop(D, type, going)", D=d)
    assert kb.holds("motion_desig(D), \\+ action_desig(D)", D=d)
    assert kb.first("desig_kind(D, K)", D=an.object(type="cup")) == {"K": "object"}


def test_interface_predicates_fail_until_extended() -> None:
    kb = install_designator_predicates(KnowledgeBase())
    assert not kb.holds("action_grounding(D, G)", D=an.action(type="x"))
    install_designator_predicates(kb)  # idempotent
    assert kb.holds("desig_prop(D, type, x)", D=an.action(type="x"))


@pytest.mark.parametrize(
    ("motion", "command"),
    [
        (a.motion(type="moving-torso", joint_angle=0.3), Term("move_torso", (0.3,))),
        (a.motion(type="looking", frame="r_gripper"), Term("move_head", ("frame", "r_gripper"))),
        (a.motion(type="looking", direction="down"), Term("move_head", ("direction", "down"))),
        (
            a.motion(type="opening", gripper="left"),
            Term("move_gripper_joint", ("left", "open", "none")),
        ),
        (
            a.motion(type="gripping", gripper="right", effort=30),
            Term("move_gripper_joint", ("right", "grip", 30)),
        ),
        (
            a.motion(type="moving-gripper-joint", gripper="left", joint_angle=0.04),
            Term("move_gripper_joint", ("left", 0.04, "none")),
        ),
        (
            a.motion(type="moving-tcp", left_target=(1, 0, 1)),
            Term("move_tcp", ("left", (1, 0, 1), "avoid_all", "none")),
        ),
        (
            a.motion(type="moving-tcp", arm="right", target=(1, 0, 1), collision_mode="allow_all"),
            Term("move_tcp", ("right", (1, 0, 1), "allow_all", "none")),
        ),
        (
            a.motion(
                type="moving-tcp",
                arm="left",
                target=(1, 0, 1),
                collision_mode="allow_hand",
                touching="mug-1",
            ),  # fmt: skip
            Term("move_tcp", ("left", (1, 0, 1), "allow_hand", "mug-1")),
        ),
        (
            a.motion(type="moving-tcp", left_target=(1, 0, 1), right_target=(2, 0, 1)),
            Term("move_tcp_both", ((1, 0, 1), (2, 0, 1), "avoid_all")),
        ),
        (
            a.motion(type="moving-arm-joints", right_configuration=[0.1, 0.2]),
            Term("move_joints", ("right", [0.1, 0.2], "avoid_all", "none")),
        ),
        (
            a.motion(
                type="moving-arm-joints",
                arm="right",
                configuration=[0.1, 0.2],
                collision_mode="allow_hand",
                touching="kitchen",
            ),  # fmt: skip
            Term("move_joints", ("right", [0.1, 0.2], "allow_hand", "kitchen")),
        ),
    ],
)
def test_common_motions_ground_to_documented_commands(
    kb: KnowledgeBase, motion: object, command: Term
) -> None:
    assert motion.reference(kb) == command  # type: ignore[attr-defined]


def test_location_targets_give_one_command_per_solution(kb: KnowledgeBase) -> None:
    target = a.location(("pose", (1, 0, 0)), ("pose", (2, 0, 0)))
    going = a.motion(type="going", target=target)
    assert going.reference(kb) == Term("move_base", ((1, 0, 0),))
    second = going.next_solution(kb)
    assert second is not None and second.reference(kb) == Term("move_base", ((2, 0, 0),))
    assert second.next_solution(kb) is None
    raw = a.motion(type="looking", target=(0, 0, 1))
    assert raw.reference(kb) == Term("move_head", ("pose", (0, 0, 1)))


def test_designator_groundings_lists_and_streams_solutions(kb: KnowledgeBase) -> None:
    loc = a.location(("pose", "p1"), ("pose", "p2"))
    with using_location_resolver(LocationResolver()):
        assert kb.first("designator_groundings(L, Ps)", L=loc) == {"Ps": ["p1", "p2"]}
        assert [s["P"] for s in kb.query("designator_grounding(L, P)", L=loc)] == ["p1", "p2"]


def test_reference_uses_the_current_kb_and_caches(kb: KnowledgeBase) -> None:
    d = a.motion(type="moving-torso", joint_angle=0.1)
    with using_kb(kb):
        first = d.reference()
    assert first is d.reference(kb) and first == Term("move_torso", (0.1,))


def test_unknown_type_names_designator_and_grounded_types(kb: KnowledgeBase) -> None:
    with pytest.raises(GroundingError) as caught:
        a.motion(type="flying", height=2).reference(kb)
    message = str(caught.value)
    assert "(a motion (type flying) (height 2))" in message
    assert "no motion_grounding rule knows type 'flying'" in message
    assert "'moving-torso'" in message and "'going'" in message
    assert set(caught.value.grounded_types) >= {"going", "looking", "moving-tcp", "gripping"}


def test_known_type_with_missing_properties_says_so(kb: KnowledgeBase) -> None:
    with pytest.raises(GroundingError, match="rules for type 'looking' did not match"):
        a.motion(type="looking", colour="red").reference(kb)


def test_grounded_types_of_an_empty_kb_is_empty() -> None:
    kb = install_designator_predicates(KnowledgeBase())
    assert grounded_types(kb, Kind.ACTION) == ()
    with pytest.raises(GroundingError, match="none \\(install a robot or environment\\)"):
        an.action(type="fetching").reference(kb)


def test_reference_without_any_kb_says_how_to_get_one() -> None:
    with pytest.raises(GroundingError, match="no knowledge base given and none is current"):
        a.motion(type="going", target=(0, 0, 0)).reference()

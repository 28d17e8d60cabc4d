"""A motion property that no grounding reads is refused by name, not ignored (issue 11)."""

from __future__ import annotations

import pytest

from robocram.designators import DesignatorPropertyError, a, install_common_motions
from robocram.logic import KnowledgeBase, Term


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    return install_common_motions(KnowledgeBase())


def test_a_misspelt_optional_property_names_the_key_and_the_near_miss(kb: KnowledgeBase) -> None:
    with pytest.raises(DesignatorPropertyError) as info:
        a.motion(type="opening", gripper="left", efort=50).reference(kb)
    assert info.value.key == "efort"
    assert "did you mean 'effort'?" in str(info.value)
    assert "'gripper'" in str(info.value)  # the known keys are listed


def test_an_unknown_property_without_a_near_miss_lists_the_known_ones(kb: KnowledgeBase) -> None:
    with pytest.raises(DesignatorPropertyError, match=r"no property 'speeed'.*'joint_angle'"):
        a.motion(type="moving-torso", joint_angle=0.2, speeed=2).reference(kb)


def test_the_correct_spelling_still_grounds(kb: KnowledgeBase) -> None:
    grounded = a.motion(type="opening", gripper="left", effort=50).reference(kb)
    assert grounded == Term("move_gripper_joint", ("left", "open", 50))

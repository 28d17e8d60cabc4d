"""The torso link and the pan-tilt links may be left out: loading takes the joints' children."""

from __future__ import annotations

import dataclasses

import pytest

from robocram.logic import KnowledgeBase
from robocram.robots import (
    DescriptionError,
    PanTiltDescription,
    install_description,
    load_description,
)
from robocram.robots.builtin import builtin_description


def test_torso_link_left_out_is_the_torso_joints_child_and_yields_the_fact() -> None:
    desc = dataclasses.replace(builtin_description("pr2"), torso_link=None)
    loaded = load_description(desc)
    assert loaded.torso_link == "torso_lift_link"
    kb = KnowledgeBase()
    install_description(kb, loaded)
    answer = kb.first("robot_torso_link_joint(pr2, L, J)")
    assert answer == {"L": "torso_lift_link", "J": "torso_lift_joint"}


def test_pan_tilt_links_left_out_are_the_joints_children() -> None:
    full = builtin_description("pr2")
    assert full.pan_tilt is not None
    short = PanTiltDescription(
        pan_joint=full.pan_tilt.pan_joint, tilt_joint=full.pan_tilt.tilt_joint
    )
    loaded = load_description(dataclasses.replace(full, pan_tilt=short))
    assert loaded.pan_tilt == load_description(full).pan_tilt
    assert loaded.pan_tilt is not None
    assert loaded.pan_tilt.axes() == (
        ("head_pan_joint", "head_pan_link"),
        ("head_tilt_joint", "head_tilt_link"),
    )


def test_an_unloaded_head_without_links_says_to_load_it() -> None:
    head = PanTiltDescription(pan_joint="head_pan_joint", tilt_joint="head_tilt_joint")
    with pytest.raises(DescriptionError, match="load the description"):
        head.axes()


def test_pan_tilt_is_keyword_only_so_a_joint_is_never_taken_for_a_link() -> None:
    with pytest.raises(TypeError):
        PanTiltDescription("head_pan_link", "head_tilt_link")  # type: ignore[misc]

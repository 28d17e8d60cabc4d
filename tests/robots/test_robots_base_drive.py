"""The base type: drafted from the wheels, kept from ``holonomic`` for older descriptions."""

from __future__ import annotations

import dataclasses
import warnings
from pathlib import Path

import pytest

from robocram.robots import DescriptionError, RobotDescription, load_description
from robocram.robots.draft.base_drive import find_base_drive
from robocram.robots.draft.model_tree import ModelTree
from tests.drafts import drafted

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
EXAMPLES = ROOT / "examples" / "robots"


def _drafted(urdf: Path) -> tuple[str | None, str, str | None]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        draft = drafted(urdf)
    return draft.description.base_type, draft.why["base_type"], draft.doubts.get("base_type")


def test_two_wheels_on_one_axle_draft_a_differential_base() -> None:
    stretch = DATA / "stretch" / "stretch_description" / "urdf" / "stretch_description.urdf"
    kind, why, doubt = _drafted(stretch)
    assert (kind, doubt) == ("differential", None)
    assert "joint_right_wheel and joint_left_wheel" in why
    kind, why, doubt = _drafted(DATA / "fetch" / "fetch_description" / "robots" / "fetch.urdf")
    assert (kind, doubt) == ("differential", None)
    assert "r_wheel_joint and l_wheel_joint" in why


def test_the_example_drafts_say_their_base_type() -> None:
    """TIAGo's two driven wheels (its casters steer), TIAGo Pro's four mecanum wheels."""
    texts = {n: (EXAMPLES / f"{n}.py").read_text(encoding="utf-8") for n in ("tiago", "tiago_pro")}
    assert 'base_type="differential"' in texts["tiago"]
    assert 'base_type="holonomic"' in texts["tiago_pro"]
    assert "mecanum" in texts["tiago_pro"]


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_robots_without_wheels_in_their_urdf_stay_holonomic_with_a_doubt(robot: str) -> None:
    desc = load_description(robot)
    assert desc.drive == "holonomic"  # the built-in descriptions, unchanged
    drive = find_base_drive(ModelTree(desc.model))
    assert drive.base_type == "holonomic"
    assert drive.doubt is not None and "'differential'" in drive.doubt


def test_holonomic_false_still_means_differential() -> None:
    old = RobotDescription("old", "robot.urdf", "base_link", holonomic=False)
    assert old.drive == "differential"
    assert RobotDescription("new", "robot.urdf", "base_link").drive == "holonomic"
    fixed = dataclasses.replace(old, base_type="fixed")
    assert fixed.drive == "fixed"  # the base type, when set, wins


def test_an_unknown_base_type_is_refused() -> None:
    with pytest.raises(DescriptionError, match="none of"):
        RobotDescription("bad", "robot.urdf", "base_link", base_type="omni")  # type: ignore[arg-type]

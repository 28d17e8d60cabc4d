"""Drafts of example-robot-data robots check clean after a few edited lines.

Each file in ``examples/robots/`` is a draft of ``robocram robot draft`` as a user edited
it. The test drafts the same URDF again, counts the lines the user changed (at most
:data:`MAX_EDITS`), and drives the edited description through the report card.
"""

from __future__ import annotations

import difflib
import importlib.util
import warnings
from pathlib import Path
from types import ModuleType

import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.robots import draft_description
from robocram.scenes import UnfitRobotError, tabletop_scene
from robocram.world import World

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "robots"
MAX_EDITS = 10  # lines a user may change in a draft (the promise)
EDITS = {  # lines each example changed from its draft
    "baxter": 0,
    "panda": 0,
    "so101": 0,
    "talos": 0,
    "tiago": 0,
    "tiago_pro": 0,
    "z1": 0,
}
CHECKED_CLEAN = ("baxter", "panda", "so101", "talos", "tiago", "tiago_pro", "z1")


def _module(path: Path) -> ModuleType:
    spec = importlib.util.spec_from_file_location(f"example_{path.stem}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def edited_lines(draft: str, edited: str) -> int:
    """Lines changed from ``draft`` to ``edited``: a replaced block counts its longer side."""
    matcher = difflib.SequenceMatcher(a=draft.splitlines(), b=edited.splitlines(), autojunk=False)
    return sum(
        max(i2 - i1, j2 - j1) for tag, i1, i2, j1, j2 in matcher.get_opcodes() if tag != "equal"
    )


def test_edited_lines_counts_changes() -> None:
    assert edited_lines("a\nb\nc\n", "a\nb\nc\n") == 0
    assert edited_lines("a\nb\nc\n", "a\nB\nc\nd\n") == 2


@pytest.mark.parametrize("name", sorted(EDITS))
def test_example_is_a_draft_with_few_edits(name: str) -> None:
    path = EXAMPLES / f"{name}.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        draft = draft_description(_module(path).URDF).source(path)
    edits = edited_lines(draft, path.read_text(encoding="utf-8"))
    assert edits == EDITS[name] <= MAX_EDITS


@pytest.mark.parametrize("name", CHECKED_CLEAN)
def test_example_checks_clean(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(description_from(str(EXAMPLES / f"{name}.py")))
    assert card.passed, card.render()
    assert len(card.results) >= 6


@pytest.mark.parametrize(("name", "arm"), [("tiago_pro", "left"), ("tiago", "arm")])
def test_pick_up_runs_unchanged_on_drafted_robots(name: str, arm: str) -> None:
    """The arm whose parked hand is nearest picks (the plan tries arms nearest first): the
    tabletop scene puts the mug before the right arm, but the TIAGo Pro's stowed right hand
    rests behind its shoulder, the left one ahead of its body, 8 cm nearer the mug."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(description_from(str(EXAMPLES / f"{name}.py")))
        try:
            with simulated_robot(scene.world, scene.robot):
                result = pick_up(scene.look_target)
            lifted = scene.world.pose("mug-1").position[2]
        finally:
            scene.world.close()
    assert (result.object_name, result.arm) == ("mug-1", arm)
    # lifted by the plan's 10 cm with the gripper holding it
    assert lifted == pytest.approx(scene.look_target.position[2] + 0.10, abs=0.02)


@pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")  # no camera
def test_a_floor_standing_arm_is_told_why_the_tabletop_scene_does_not_fit() -> None:
    desc = description_from(str(EXAMPLES / "z1.py"))
    too_low = r"shoulder of its 'arm' arm is 0\.06 m above the floor, too low"
    with World() as world, pytest.raises(UnfitRobotError, match=too_low):
        tabletop_scene(desc, world)

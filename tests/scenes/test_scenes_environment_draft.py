"""Environment descriptions drafted from URDFs (issue 25, items 4-6): PyCRAM's two worlds.

tests/data/pycram holds PyCRAM's kitchen.urdf and apartment.urdf (GPL-3, with its LICENSE),
unchanged; their meshes are not there, so mesh-only links are frames without shapes unless
a stand-in gives them a box (drawers, tables, counter tops: tests/scenes/test_scenes_stand_ins.py).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.cli import main
from robocram.scenes import draft_environment
from robocram.scenes.environment_check import check_environment, environment_from

DATA = Path(__file__).resolve().parents[1] / "data" / "pycram"


def test_pycram_kitchen_drawers_doors_handles_and_surfaces() -> None:
    draft = draft_environment(DATA / "kitchen.urdf")
    desc = draft.description
    drawers = [c for c in desc.containers if c.kind == "drawer"]
    doors = [c for c in desc.containers if c.kind == "door"]
    assert len(drawers) == 15  # every prismatic joint of the URDF (a 16th is in a comment)
    assert [d.link for d in doors] == ["iai_fridge_main"]
    fridge = doors[0]
    assert (fridge.joint, fridge.handle) == ("iai_fridge_door_joint", "iai_fridge_door_handle")
    assert fridge.opening == pytest.approx(1.3708)  # 1.5708 rad limit less 0.2
    assert all(d.handle == d.link.replace("_main", "_handle") for d in drawers)
    assert {d.opening for d in drawers} == {0.43}  # 0.48 m limit less 0.05
    island = desc.container("kitchen_island_left_upper_drawer_main")
    assert island is not None and island.front == pytest.approx(0.0)
    sink = desc.container("sink_area_left_upper_drawer_main")
    assert sink is not None and sink.front == pytest.approx(3.1416, abs=1e-4)
    surfaces = {s.link: s.height for s in desc.surfaces}
    assert surfaces == pytest.approx(
        {"kitchen_island_surface": 0.861, "sink_area_surface": 0.85, "table_area_main": 0.75}
    )  # the table's top is its stand-in's, a guessed 0.75 m
    assert any("oven_area_oven_knob_stove_1_joint" in d for d in draft.doubts)  # knobs left out


def test_pycram_apartment_drawers_doors_handles_and_surfaces() -> None:
    draft = draft_environment(DATA / "apartment.urdf")
    desc = draft.description
    drawers = [c for c in desc.containers if c.kind == "drawer"]
    doors = [c for c in desc.containers if c.kind == "door"]
    assert len(drawers) == 23
    assert len(doors) == 8
    by_name = {c.handle for c in desc.containers if "handle" in c.handle}
    assert len(by_name) == 27  # four drawers have no handle link: doubts
    assert sum("no handle found" in d for d in draft.doubts) == 4
    top = desc.container("cabinet10_drawer_top")
    assert top is not None and top.handle == "handle_cab10_t" and top.opening == 0.4
    wardrobe = [c for c in doors if c.link == "wardrobe"]
    assert {c.handle for c in wardrobe} == {
        "wardrobe_door_left_handle",
        "wardrobe_door_right_handle",
    }
    surfaces = {s.link: s.height for s in desc.surfaces}
    assert surfaces == pytest.approx(
        {
            "bedside_table": 0.46,
            "coffee_table": 0.4,
            "island_countertop": 0.942,  # stand-ins: 2 cm over their frames
            "countertop": 0.928,
            "table_area_main": 0.75,
        }
    )


@pytest.mark.parametrize(("urdf", "checks"), [("kitchen.urdf", 19), ("apartment.urdf", 36)])
def test_the_environment_check_passes_on_both(urdf: str, checks: int) -> None:
    card = check_environment(draft_environment(DATA / urdf).description)
    assert card.passed, card.render()
    assert len(card.lines) == checks


def test_env_draft_then_env_check_on_the_command_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "apartment.py"
    assert main(["env", "draft", str(DATA / "apartment.urdf"), "-o", str(out)]) == 0
    text = out.read_text("utf-8")
    assert text.count("# TODO doubt:") == 16
    assert environment_from(out).name == "apartment"
    assert main(["env", "check", str(out)]) == 0
    assert "36 of 36 checks pass" in capsys.readouterr().out

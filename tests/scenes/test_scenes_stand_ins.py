"""Stand-ins for missing meshes (issue 25, item 6): drawers get an open box, tables a top.

PyCRAM's kitchen.urdf and apartment.urdf name meshes under ``package://iai_kitchen`` and
``package://iai_apartment`` that are not shipped; their drafts give those links boxes.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.scenes import StandIn, draft_environment
from robocram.scenes.environment_model import EnvironmentModel, loadable_urdf
from robocram.world import World

DATA = Path(__file__).resolve().parents[1] / "data" / "pycram"


def test_an_open_box_is_a_floor_and_four_walls_inside_its_outline() -> None:
    shape = StandIn("drawer", "open_box", (0.5, 0.4, 0.12), (0.1, 0.0, 0.05))
    boxes = shape.boxes()
    assert len(boxes) == 5
    (floor_at, floor_size), *walls = boxes
    assert floor_size == pytest.approx((0.5, 0.4, 0.01))
    assert floor_at[2] - floor_size[2] / 2 == pytest.approx(0.05 - 0.06)  # the outline's bottom
    for at, size in walls:
        assert at[2] + size[2] / 2 == pytest.approx(0.05 + 0.06)  # walls reach the rim
        for axis, extent in enumerate((0.5, 0.4)):
            low = at[axis] - size[axis] / 2 - (0.1, 0.0)[axis]
            assert low >= -extent / 2 - 1e-9
    assert StandIn("top", "box", (1.0, 0.5, 0.04)).boxes() == (((0.0, 0.0, 0.0), (1.0, 0.5, 0.04)),)
    top, *legs = StandIn("t", "table", (1.2, 0.8, 0.75), (0.0, 0.0, 0.375)).boxes()
    assert top == ((0.0, 0.0, 0.73), (1.2, 0.8, 0.04))  # its upper face at 0.75 m
    corners = sorted((round(at[0], 6), round(at[1], 6)) for at, _ in legs)
    assert corners == [(-0.575, -0.375), (-0.575, 0.375), (0.575, -0.375), (0.575, 0.375)]
    assert all(at[2] - size[2] / 2 == pytest.approx(0.0) for at, size in legs)  # on the floor
    with pytest.raises(ValueError, match="positive"):
        StandIn("flat", "box", (1.0, 0.0, 0.1))


def test_the_kitchen_drawers_and_table_stand_in_for_their_meshes() -> None:
    draft = draft_environment(DATA / "kitchen.urdf")
    shapes = {s.link: s for s in draft.description.stand_ins}
    drawers = [c.link for c in draft.description.containers if c.kind == "drawer"]
    # every drawer but the one built of boxes (oven_area_area_right_drawer_main)
    assert sorted(k for k, s in shapes.items() if s.kind == "open_box") == sorted(
        d for d in drawers if d != "oven_area_area_right_drawer_main"
    )
    island = shapes["kitchen_island_left_upper_drawer_main"]
    # 0.48 m of travel + 5 cm deep, 0.8 m spacing to the next drawer less 3 cm, 12 cm high
    assert island.size == pytest.approx((0.53, 0.77, 0.12))
    # its rim 4 cm over the handle (0.11 m up its frame), its front 3 cm behind the handle
    assert island.centre == pytest.approx((0.0375, 0.0, 0.09))
    table = shapes["table_area_main"]
    assert (table.kind, table.size, table.centre) == ("table", (1.2, 0.8, 0.75), (0.0, 0.0, 0.375))
    table_doubt = [s.doubt for s in draft.stand_ins if s.stand_in.link == "table_area_main"]
    assert table_doubt[0] is not None and "guess" in table_doubt[0]


def test_the_apartment_counter_tops_reach_past_what_stands_on_them() -> None:
    draft = draft_environment(DATA / "apartment.urdf")
    shapes = {s.link: s for s in draft.description.stand_ins}
    assert sum(s.kind == "open_box" for s in shapes.values()) == 22
    assert {k for k, s in shapes.items() if s.kind == "box"} == {"countertop", "island_countertop"}
    assert shapes["table_area_main"].kind == "table"
    # the coffee machine stands 0.3 m off the countertop's frame: 0.3 m more each side
    assert shapes["countertop"].size == pytest.approx((0.6, 1.2, 0.04))
    top = shapes["cabinet10_drawer_top"]
    assert top.size == pytest.approx((0.5, 0.471, 0.112))  # 0.5 m to cabinet9, 0.142 below


def test_the_loadable_copy_gives_the_stand_ins_collision_boxes(tmp_path: Path) -> None:
    desc = draft_environment(DATA / "kitchen.urdf").description
    copy = loadable_urdf(desc.urdf, desc.stand_ins, tmp_path)
    model = EnvironmentModel.from_file(copy)
    assert len(model.boxes["kitchen_island_left_upper_drawer_main"]) == 5
    top, *legs = model.boxes["table_area_main"]
    assert top.size == (1.2, 0.8, 0.04) and len(legs) == 4
    world = World()
    try:
        env = world.add_urdf("kitchen", copy, type="environment")
        low, high = world.contacts.link_aabb(env, "table_area_main")
        assert high[2] == pytest.approx(0.75, abs=0.01)
        assert high[0] - low[0] == pytest.approx(1.2, abs=0.01)
    finally:
        world.close()


def test_the_draft_writes_each_stand_in_with_why_and_the_guesses_as_doubts() -> None:
    text = draft_environment(DATA / "apartment.urdf").source()
    assert text.count("            StandIn(") == 25
    assert text.count("# why: cabinet") > 0 and "an open box 0.50 deep" in text
    # the table and the two counter tops are guesses: one doubt each, above their StandIn
    doubts = [line for line in text.splitlines() if "# TODO doubt:" in line]
    assert sum("in a missing mesh" in line for line in doubts) == 3
    assert 'StandIn("table_area_main", "table", size=(1.2, 0.8, 0.75)' in text

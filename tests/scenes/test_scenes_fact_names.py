"""Every fact written as text from names reads back as exactly those names (issue 42, bad 1).

A link named like a directive must not run it, and a link named like a variable must not
become one: the scene's usual places, the description's facts and the process modules'
matching facts all write names through ``name_atom``.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robocram.cli import main
from robocram.execution import matching_facts
from robocram.knowledge.scene_predicates import (
    CONTAINER,
    CONTAINER_KIND,
    SUPPORTING_SURFACE,
    USUAL_LOCATION,
)
from robocram.logic import KnowledgeBase
from robocram.scenes import (
    ContainerDescription,
    EnvironmentDescription,
    SurfaceDescription,
    draft_environment,
    environment_scene,
)
from robocram.scenes.environment_check import environment_from
from robocram.scenes.environment_scene import ItemPlace, usual_location_facts
from robocram.scenes.kitchen_scene import kitchen_urdf

DIRECTIVE = "t). :- retractall(supporting_surface(_, _)), assertz(pwned). %"
HOSTILE = (DIRECTIVE, "X", "Table_top", "[]", "a\nb", '"""', "back\\slash", "it's")


def _description(name: str) -> EnvironmentDescription:
    return EnvironmentDescription(
        name=name,
        urdf=Path("unused.urdf"),
        surfaces=(SurfaceDescription(name, 0.9),),
        containers=(ContainerDescription(name, name, name, "drawer", 0.3),),
        usual_locations=((name, name),),
    )


@pytest.mark.parametrize("name", HOSTILE)
def test_description_facts_read_back_exactly(name: str) -> None:
    kb = KnowledgeBase()
    kb.consult(_description(name).facts(name), group="semantics")
    assert [(r.environment, r.link) for r in SUPPORTING_SURFACE.answers(kb)] == [(name, name)]
    assert [(r.link, r.joint, r.handle) for r in CONTAINER.answers(kb)] == [(name, name, name)]
    assert [r.kind for r in CONTAINER_KIND.answers(kb)] == ["drawer"]
    assert [(r.type, r.link) for r in USUAL_LOCATION.answers(kb)] == [(name, name)]
    assert not kb.defines("pwned/0")


@settings(max_examples=100, deadline=None, database=None)
@given(st.text(), st.text())
def test_every_name_pair_reads_back_from_the_description_facts(link: str, kind: str) -> None:
    desc = replace(_description(link), name=kind, usual_locations=((kind, link),))
    kb = KnowledgeBase()
    kb.consult(desc.facts(), group="semantics")
    assert [(r.environment, r.link) for r in SUPPORTING_SURFACE.answers(kb)] == [(kind, link)]
    assert [(r.type, r.environment, r.link) for r in USUAL_LOCATION.answers(kb)] == [
        (kind, kind, link)
    ]


@pytest.mark.parametrize("name", HOSTILE)
def test_scene_usual_places_read_back_exactly(name: str) -> None:
    kb = KnowledgeBase()
    placed = [ItemPlace("item-1", name, name, (0.0, 0.0))]
    kb.consult(usual_location_facts(_description("k"), placed, name), group="contents")
    rows = list(USUAL_LOCATION.answers(kb))
    assert [(r.type, r.environment, r.link) for r in rows] == [(name, name, name)]
    assert not USUAL_LOCATION.holds(kb, type="bowl")  # a name like a variable matches nothing


@pytest.mark.parametrize("prefix", ["Projection", "it's"])
def test_matching_facts_keep_the_module_names(prefix: str) -> None:
    kb = KnowledgeBase()
    kb.consult(matching_facts(prefix, ["arms"]), group="matching")
    modules = {a["PM"] for a in kb.query("available_process_module(PM)")}
    assert modules == {f"{prefix}_arms"}


def test_environment_scene_items_on_hostile_links(tmp_path: Path) -> None:
    text = kitchen_urdf().read_text("utf-8")
    urdf = tmp_path / "kitchen.urdf"
    urdf.write_text(
        text.replace('"counter_top_north"', f'"{DIRECTIVE}"').replace(
            '"counter_top_east"', '"Table_top"'
        )
    )
    description = draft_environment(urdf, name="kitchen").description
    items = (
        ItemPlace("mug-1", "mug", DIRECTIVE, (0.15, -0.08)),
        ItemPlace("milk-1", "milk", "Table_top", (0.0, -0.3)),
    )
    scene = environment_scene(description, "pr2", items, (-0.8, 0.2, 0.0))
    try:
        kb = scene.world.kb
        surfaces = {r.link for r in SUPPORTING_SURFACE.answers(kb, environment="kitchen")}
        assert {DIRECTIVE, "Table_top"} <= surfaces and len(surfaces) > 2
        assert not kb.defines("pwned/0")
        assert [r.link for r in USUAL_LOCATION.answers(kb, type="mug")] == [DIRECTIVE]
        assert [r.link for r in USUAL_LOCATION.answers(kb, type="milk")] == ["Table_top"]
        assert not USUAL_LOCATION.holds(kb, type="bowl", link="sink_area_surface")
    finally:
        scene.world.close()


def test_a_draft_of_hostile_link_names_loads_back_with_them(tmp_path: Path) -> None:
    names = {"a&#10;b": "a\nb", "&quot;&quot;&quot;": '"""', "back\\slash": "back\\slash"}
    board = '<collision><geometry><box size="0.6 0.6 0.05"/></geometry></collision>'
    parts = ['<link name="floor"/>']
    for i, xml_name in enumerate(names):
        parts.append(f'<link name="{xml_name}">{board}</link>')
        parts.append(
            f'<joint name="j{i}" type="fixed"><parent link="floor"/><child link="{xml_name}"/>'
            f'<origin xyz="{i} 0 0.8"/></joint>'
        )
    urdf = tmp_path / "boards.urdf"
    urdf.write_text(f'<robot name="boards">{"".join(parts)}</robot>', "utf-8")
    out = tmp_path / "boards.py"
    assert main(["env", "draft", str(urdf), "-o", str(out)]) == 0
    loaded = environment_from(out)
    assert {s.link for s in loaded.surfaces} == set(names.values())

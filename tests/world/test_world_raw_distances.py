"""RawDistances: PyBullet's own bounds and closest points of single links, by name."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from robocram.world import RawDistances, UnknownLinkError, World


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.add_box("a", (0.2, 0.2, 0.2), (0.0, 0.0, 0.5))
        w.add_box("b", (0.2, 0.2, 0.2), (0.17, 0.0, 0.5))  # 3 cm into a
        w.add_robot("pr2")
        yield w


def test_closest_points_give_the_penetration_depth_and_nothing_beyond_reach(world: World) -> None:
    raw = RawDistances(world)
    (a_link,), (b_link,) = raw.collision_links("a"), raw.collision_links("b")
    gap = raw.closest("a", a_link, "b", b_link)
    assert gap is not None and gap.distance == pytest.approx(-0.03, abs=1e-4)
    world.set_pose("b", (0.5, 0.0, 0.5))  # 30 cm apart
    assert raw.closest("a", a_link, "b", b_link, reach=0.1) is None
    far = raw.closest("a", a_link, "b", b_link, reach=0.5)
    assert far is not None and far.distance == pytest.approx(0.3, abs=1e-4)


def test_bounds_are_per_link_and_links_without_shapes_are_not_listed(world: World) -> None:
    raw = RawDistances(world)
    links = raw.collision_links("pr2")
    assert "base_link" in links and "r_gripper_tool_frame" not in links
    ((low, high),) = raw.link_bounds("a", raw.collision_links("a"))
    assert low[0] <= -0.1 and high[0] >= 0.1 and high[0] < 0.11
    with pytest.raises(UnknownLinkError, match="did you mean"):
        raw.closest("pr2", "base_lnk", "a", raw.collision_links("a")[0])


def test_asked_for_exactly_zero_bullet_misses_a_penetration_of_one_bodys_links() -> None:
    """Why the audit asks a hair beyond 0 (penetration_audit.QUERY_REACH)."""
    with World() as world:
        world.add_robot("hsrb")
        world.set_joint_states("hsrb", dict(world.robot("hsrb").description.arms["arm"].parking))
        world.set_joint_states("hsrb", {"hand_motor_joint": 1.24})  # the open hand
        raw = RawDistances(world)
        assert raw.closest("hsrb", "base_link", "hsrb", "hand_r_distal_link", 0.0) is None
        gap = raw.closest("hsrb", "base_link", "hsrb", "hand_r_distal_link", 1e-6)
        assert gap is not None and gap.distance == pytest.approx(-0.0066, abs=2e-4)


def _box_link(name: str, size: str, xyz: str = "0 0 0") -> str:
    shape = f'<geometry><box size="{size}"/></geometry>'
    return (
        f'<link name="{name}"><collision><origin xyz="{xyz}"/>{shape}</collision>'
        f'<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/>'
        f"</inertial></link>"
    )


CABINET = (
    '<robot name="cabinet">'
    + _box_link("body", "0.4 0.4 0.6")
    + _box_link("door", "0.02 0.4 0.6", "0 -0.2 0")
    + _box_link("handle", "0.02 0.02 0.1")
    + _box_link("drawer", "0.3 0.3 0.1")
    + '<joint name="door_joint" type="revolute"><parent link="body"/><child link="door"/>'
    '<origin xyz="0.21 0.2 0"/><limit lower="0" upper="1.5"/></joint>'
    '<joint name="handle_joint" type="fixed"><parent link="door"/><child link="handle"/>'
    '<origin xyz="0.03 -0.35 0"/></joint>'
    '<joint name="drawer_joint" type="prismatic"><parent link="body"/><child link="drawer"/>'
    '<origin xyz="0 0 0.4"/><limit lower="0" upper="0.3"/></joint>'
    "</robot>"
)


def test_a_joint_moves_the_links_below_it_as_their_bounds_show(tmp_path: Path) -> None:
    """The audit re-reads only these while the hand carries the joint."""
    path = tmp_path / "cabinet.urdf"
    path.write_text(CABINET, encoding="utf-8")
    with World() as world:
        world.add_urdf("cabinet", path, (1.0, 0.0, 0.5))
        raw = RawDistances(world)
        links = raw.collision_links("cabinet")
        before = raw.link_bounds("cabinet", links)
        world.set_joint_states("cabinet", {"door_joint": 0.7})
        after = raw.link_bounds("cabinet", links)
        changed = [link for link, b, a in zip(links, before, after, strict=True) if b != a]
        assert sorted(changed) == ["door", "handle"]
        assert sorted(raw.links_moved_by("cabinet", "door_joint")) == sorted(changed)
        assert raw.links_moved_by("cabinet", "drawer_joint") == ["drawer"]


def test_asked_by_slot_the_answers_are_those_asked_by_name(world: World) -> None:
    raw = RawDistances(world)
    links = raw.collision_links("pr2")
    read = raw.slot_bounds(raw.slots("pr2", links))
    assert read.shape == (len(links), 2, 3)
    assert read.tolist() == [[list(low), list(high)] for low, high in raw.link_bounds("pr2", links)]
    (a,), (b,) = raw.slots("a", raw.collision_links("a")), raw.slots("b", raw.collision_links("b"))
    gap = raw.closest("a", "a", "b", "b", 1e-4)
    assert raw.slot_closest(a, b, 1e-4) == gap
    assert gap is not None and raw.slot_distance(a, b, 1e-4) == gap.distance  # 3 cm deep
    assert gap.distance == pytest.approx(-0.03, abs=1e-6)
    world.set_pose("b", (0.5, 0.0, 0.5))  # 30 cm apart: nothing within reach
    assert raw.slot_distance(a, b, 1e-4) is None

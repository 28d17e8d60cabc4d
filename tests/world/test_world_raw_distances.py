"""RawDistances: PyBullet's own bounds and closest points of single links, by name."""

from __future__ import annotations

from collections.abc import Iterator

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

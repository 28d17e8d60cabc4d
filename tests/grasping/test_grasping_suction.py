"""A suction hand's grasps: the tool frame on a face, no opening needed."""

from __future__ import annotations

import math

import pytest

from robocram.grasping import Hand, ObjectShape, ObjectUngraspable, grasps
from robocram.tf import Pose

SUCTION = Hand(max_opening=math.inf, finger_depth=0.0, suction=True)
MUG = ObjectShape("mug", (-0.044, -0.044, 0.0), (0.044, 0.084, 0.103), handle=0.012)
BOWL = ObjectShape("bowl", (-0.08, -0.08, 0.0), (0.08, 0.08, 0.06), wall=0.006)


def test_a_suction_hand_touches_a_mugs_top_over_its_body() -> None:
    found = grasps(MUG, SUCTION)
    assert [g.name for g in found[:4]] == ["top"] * 4
    for grasp in found[:4]:
        assert grasp.tool.position == pytest.approx((0.0, 0.0, 0.103))  # axis, not handle
        assert grasp.approach == (0.0, 0.0, -1.0) and grasp.opening == 0.0
        # the hand's approach axis (tool x) points down in the object's frame
        down = grasp.tool * Pose((1.0, 0.0, 0.0))
        assert down.position == pytest.approx((0.0, 0.0, 0.103 - 1.0), abs=1e-9)


def test_a_hollow_object_is_touched_on_its_rim() -> None:
    found = grasps(BOWL, SUCTION, ("rim",))
    assert {g.name for g in found} == {"rim"}
    for grasp in found:
        x, y, z = grasp.tool.position
        assert math.hypot(x, y) == pytest.approx(0.08 - 0.003) and z == pytest.approx(0.06)


def test_a_suction_hand_refuses_grasps_it_cannot_take_naming_them() -> None:
    with pytest.raises(ObjectUngraspable, match=r"only by a face .* allow front, handle"):
        grasps(MUG, SUCTION, ("front", "handle"))


def test_the_side_comes_after_the_top_on_each_side_without_the_handle() -> None:
    found = grasps(MUG, SUCTION)
    assert [g.name for g in found] == ["top"] * 4 + ["side"] * 12  # 3 sides, 4 turns
    for grasp in found[4:]:
        x, y, z = grasp.tool.position
        ax, ay, az = grasp.approach
        assert az == 0.0 and z == pytest.approx(0.103 / 2)  # level, at half height
        assert math.hypot(x, y) == pytest.approx(0.044)  # on the body's side
        assert (x, y) == pytest.approx((-0.044 * ax, -0.044 * ay))  # coming in to the axis
        assert y < 0.05  # never on the handle's side (+y)
        start = grasp.pre_grasp_tool().position
        assert math.dist(start, grasp.tool.position) == pytest.approx(0.10)
        # the hand's approach axis (tool x) is the grasp's
        ahead = (grasp.tool * Pose((1.0, 0.0, 0.0))).position
        assert ahead == pytest.approx((x + ax, y + ay, z), abs=1e-9)


def test_a_bowl_is_touched_on_its_rim_then_its_side() -> None:
    names = [g.name for g in grasps(BOWL, SUCTION)]
    assert names == ["rim"] * 16 + ["side"] * 16

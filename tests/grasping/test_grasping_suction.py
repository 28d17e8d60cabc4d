"""A suction hand's grasps: the tool frame on a face from above, no opening needed."""

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
    assert {g.name for g in found} == {"top"} and len(found) == 4
    for grasp in found:
        assert grasp.tool.position == pytest.approx((0.0, 0.0, 0.103))  # axis, not handle
        assert grasp.approach == (0.0, 0.0, -1.0) and grasp.opening == 0.0
        # the hand's approach axis (tool x) points down in the object's frame
        down = grasp.tool * Pose((1.0, 0.0, 0.0))
        assert down.position == pytest.approx((0.0, 0.0, 0.103 - 1.0), abs=1e-9)


def test_a_hollow_object_is_touched_on_its_rim() -> None:
    found = grasps(BOWL, SUCTION)
    assert {g.name for g in found} == {"rim"}
    for grasp in found:
        x, y, z = grasp.tool.position
        assert math.hypot(x, y) == pytest.approx(0.08 - 0.003) and z == pytest.approx(0.06)


def test_a_suction_hand_refuses_grasps_it_cannot_take_naming_them() -> None:
    with pytest.raises(ObjectUngraspable, match=r"only from above .* allow front, handle"):
        grasps(MUG, SUCTION, ("front", "handle"))

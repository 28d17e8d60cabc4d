"""The grasp model: grasps from an object's box and a hand's width, with the values that matter."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from robocram.grasping import (
    CLEARANCE,
    Hand,
    ObjectShape,
    ObjectUngraspable,
    UnknownGraspError,
    grasps,
)
from robocram.grasping.grasp_model import (
    LIFT,
    PADS_BEHIND_DEEP,
    PRE_GRASP,
    RIM_DEEP_FLOOR,
    RIM_DEPTH,
    TOP_STRADDLE,
)
from robocram.tf import quaternion as quat

PR2_HAND = Hand(max_opening=0.0937)  # x approach, y opening, as the PR2's tool frame
MILK = ObjectShape("milk-1", (-0.035, -0.035, -0.1), (0.035, 0.035, 0.1))  # origin at centre
CEREAL = ObjectShape("cereal-1", (-0.035, -0.095, -0.14), (0.035, 0.095, 0.14))
BOWL = ObjectShape("bowl-1", (-0.08, -0.08, 0.0), (0.08, 0.08, 0.06), wall=0.006)
MUG = ObjectShape("mug-1", (-0.041, -0.041, 0.0), (0.041, 0.081, 0.1), handle=0.012)


def _axes(grasp_tool_orientation: tuple[float, ...], hand: Hand) -> tuple[np.ndarray, np.ndarray]:
    """The hand's approach and opening axes in the object frame."""
    m = quat.to_matrix(grasp_tool_orientation)  # type: ignore[arg-type]
    return m @ np.asarray(hand.approach), m @ np.asarray(hand.opening)


def test_a_top_grasp_of_the_milk_box_closes_across_its_side_at_its_centre() -> None:
    found = grasps(MILK, PR2_HAND, ("top",))
    assert [round(g.turn, 6) for g in found] == [0.0, round(math.pi, 6), 1.570796, -1.570796]
    first = found[0]
    x, y, z = first.tool.position
    assert (x, y) == pytest.approx((0.0, 0.0), abs=1e-12)
    assert z == pytest.approx(0.1 - TOP_STRADDLE)  # fingers 4 cm down from the top
    assert first.opening == pytest.approx(0.07 + CLEARANCE)
    approach, opening = _axes(first.tool.orientation, PR2_HAND)
    assert approach == pytest.approx((0.0, 0.0, -1.0), abs=1e-9)
    assert opening == pytest.approx((1.0, 0.0, 0.0), abs=1e-9)  # turn 0: across x
    assert (first.pre_grasp, first.lift) == (PRE_GRASP, LIFT)
    assert first.pre_grasp_tool().position == pytest.approx((0.0, 0.0, z + PRE_GRASP))


def test_a_low_object_is_grasped_at_half_height_a_tall_one_4_cm_below_its_top() -> None:
    """The fingers straddle a body no deeper than 4 cm: behind its tips a hand narrows
    (the PR2's finger links went 6.5 mm into a mug's wall 5.6 cm down, issue 35)."""
    flat = ObjectShape("box", (-0.03, -0.03, 0.0), (0.03, 0.03, 0.06))
    assert grasps(flat, PR2_HAND, ("top",))[0].tool.position[2] == pytest.approx(0.03)
    tall = ObjectShape("box", (-0.03, -0.03, 0.0), (0.03, 0.03, 0.11))
    assert grasps(tall, PR2_HAND, ("top",))[0].tool.position[2] == pytest.approx(0.07)


def test_only_the_narrow_side_of_the_cereal_box_fits_the_pr2_hand() -> None:
    found = grasps(CEREAL, PR2_HAND, ("top", "front", "left", "right"))
    assert {g.name for g in found} == {"top", "left", "right"}  # front spans the 0.19 m side
    assert all(g.opening == pytest.approx(0.07 + CLEARANCE) for g in found)
    assert {round(g.turn, 6) for g in found if g.name == "top"} == {0.0, round(math.pi, 6)}


def test_side_grasps_come_in_level_from_their_side() -> None:
    front, left, right = (grasps(MILK, PR2_HAND, (n,))[0] for n in ("front", "left", "right"))
    assert front.approach == (1.0, 0.0, 0.0) and front.tool.position[0] == pytest.approx(0.0)
    assert left.approach == (0.0, -1.0, 0.0) and right.approach == (0.0, 1.0, 0.0)
    assert front.tool.position[2] == pytest.approx(0.0)  # half height of the box
    approach, opening = _axes(left.tool.orientation, PR2_HAND)
    assert approach == pytest.approx(left.approach, abs=1e-9)
    assert abs(opening[0]) == pytest.approx(1.0)  # the fingers close across x


def test_the_bowl_rim_grasp_straddles_its_wall() -> None:
    assert len(grasps(BOWL, PR2_HAND, ("rim",))) == 8  # four places, two turns: none deep
    behind = replace(PR2_HAND, pads_behind=PADS_BEHIND_DEEP)  # pads end behind the tool
    rims = grasps(BOWL, behind, ("rim",))
    assert len(rims) == 16  # four places round the rim, two turns each; then each deep
    assert all(g.opening == pytest.approx(0.006 + CLEARANCE) for g in rims)
    for k, g in enumerate(rims):
        x, y, z = g.tool.position
        assert math.hypot(x, y) == pytest.approx(0.08 - 0.003)  # on the wall's middle
        deep = k >= 8  # after the others
        assert z == pytest.approx(RIM_DEEP_FLOOR if deep else 0.06 - RIM_DEPTH)
        assert g.deeper == pytest.approx(0.06 - RIM_DEPTH - RIM_DEEP_FLOOR if deep else 0.0)
        approach, opening = _axes(g.tool.orientation, PR2_HAND)
        assert approach == pytest.approx((0.0, 0.0, -1.0), abs=1e-9)
        radial = np.asarray((x, y, 0.0)) / math.hypot(x, y)
        assert abs(float(opening @ radial)) == pytest.approx(1.0)  # fingers across the wall
    assert {g.name for g in grasps(MILK, PR2_HAND, ("rim", "top"))} == {"top"}  # solid: no rim


def test_a_narrow_hand_takes_the_mug_by_its_handle_only() -> None:
    narrow = Hand(max_opening=0.071)  # TIAGo Pro's hand
    found = grasps(MUG, narrow)
    assert {g.name for g in found} == {"handle"}
    handle = found[0]
    assert handle.opening == pytest.approx(0.012 + CLEARANCE)
    assert handle.approach == (0.0, -1.0, 0.0)  # towards the body, from the handle's side
    x, y, z = handle.tool.position
    assert x == pytest.approx(0.0) and 0.041 < y < 0.081 and z == pytest.approx(0.05)


def test_a_hand_narrower_than_the_body_takes_the_handle_from_above_too() -> None:
    """After the side grasps: from above, the tool on the bar's middle (the box's end less
    half the bar), then 1.5 and 3 cm farther out, the fingers across the bar (x)."""
    found = [g for g in grasps(MUG, Hand(max_opening=0.08)) if g.approach == (0.0, 0.0, -1.0)]
    assert {g.name for g in found} == {"handle"} and len(found) == 6
    places = sorted({round(g.tool.position[1], 6) for g in found})
    assert places == pytest.approx([0.081 - 0.006, 0.081 - 0.006 + 0.015, 0.081 - 0.006 + 0.03])
    for g in found:
        x, _, z = g.tool.position
        assert x == pytest.approx(0.0) and z == pytest.approx(0.1 - TOP_STRADDLE)
        assert abs(g.across[0]) == pytest.approx(1.0)
        _, opening = _axes(g.tool.orientation, Hand())
        assert abs(opening[0]) == pytest.approx(1.0)


def test_a_hand_wide_enough_for_the_body_gets_no_handle_from_above() -> None:
    found = grasps(MUG, PR2_HAND)
    assert not [g for g in found if g.name == "handle" and g.approach == (0.0, 0.0, -1.0)]
    only_handle = grasps(MUG, PR2_HAND, ("handle",))  # the body not allowed: it does not fit
    assert any(g.approach == (0.0, 0.0, -1.0) for g in only_handle)


def test_no_side_grasp_comes_in_through_the_handle() -> None:
    names = [g.name for g in grasps(MUG, Hand(max_opening=0.13))]
    assert "left" not in names  # the handle sticks out on +y
    assert {"top", "front", "right", "handle"} <= set(names)


def test_a_too_narrow_hand_gets_no_grasp_and_the_error_names_both_widths() -> None:
    with pytest.raises(ObjectUngraspable) as info:
        grasps(MILK, Hand(max_opening=0.05))
    err = info.value
    assert (err.object, err.hand_width) == ("milk-1", 0.05)
    assert err.needed_width == pytest.approx(0.07 + CLEARANCE)
    assert "0.050 m" in str(err) and "0.072 m" in str(err) and "milk-1" in str(err)


def test_an_unknown_grasp_name_lists_the_known_ones() -> None:
    with pytest.raises(UnknownGraspError, match="unknown grasp 'sideways'; grasps: top, front"):
        grasps(MILK, PR2_HAND, ("sideways",))


def test_a_turned_hand_maps_its_own_axes_onto_the_grasp() -> None:
    """A hand whose approach is its z axis (not our x convention) gets the same grasps."""
    z_hand = Hand(approach=(0.0, 0.0, 1.0), opening=(1.0, 0.0, 0.0), max_opening=0.0937)
    for mine, theirs in zip(grasps(MILK, PR2_HAND), grasps(MILK, z_hand), strict=True):
        assert mine.tool.position == theirs.tool.position
        a1, o1 = _axes(mine.tool.orientation, PR2_HAND)
        a2, o2 = _axes(theirs.tool.orientation, z_hand)
        assert a1 == pytest.approx(a2, abs=1e-9) and o1 == pytest.approx(o2, abs=1e-9)

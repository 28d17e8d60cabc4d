"""Kitchen transports hold the hand to what it acts on, 5 mm deep at most, and say so.

Each ``allow_hand`` motion (approach, lift, put down, back off) stores its allowance:
the hand's links on the object moved, 5 mm. The audit replays every trajectory on raw
PyBullet and holds it to that bound (clean). Where each such motion ends, PyBullet's raw
closest points say how deep the hand is in the named object (within the bound) and that
it touches no other body (``kitchen_transports.HandEnds``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.costmaps.reach_reasoning import LIFT_MARGIN
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.scenes import kitchen_scene
from robocram.traces.audit_findings import FindingKind
from tests.kitchen_transports import SHARED, Transports

pytestmark = SHARED  # its kitchen transports are other modules' too (tests/kitchen_transports.py)


def _bottom_and_drawer_top(robot: str) -> tuple[float, float]:
    """[m] The bowl's bottom and its drawer's top, as the kitchen starts (the drawer
    slides level: both stay at these heights when it is open)."""
    scene = kitchen_scene(robot)
    boxes = scene.world.contacts
    bottom = min(low[2] for low, _ in boxes.link_aabbs("bowl-1").values())
    top = boxes.link_aabbs("kitchen")[DRAWER][1][2]
    scene.world.close()
    return bottom, top


DRAWER = "drawer_unit_drawer_3"
STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")


@pytest.mark.parametrize(
    "robot",
    [
        "pr2",
        "hsrb",
        "boxy",
        # its grip centres the hand (curved finger hulls meet the mug 6 mm apart) and its
        # base backs the hand off the mug: a drive held to the bound, not a sweep through it
        pytest.param(STRETCH, id="stretch"),
    ],
)
def test_a_kitchen_mug_transport_is_clean_with_the_hand_bounded_on_the_mug(
    kitchen_transports: Transports, robot: str
) -> None:
    traced = kitchen_transports(robot, "mug")
    report, ends = traced.report, traced.ends
    assert report.clean, report.summary_lines()
    assert len(ends.named) >= 3  # approach, lift, put down (and back off)
    assert all(named == {"mug-1"} for named in ends.named)  # only the mug, by name
    assert max(ends.depths) <= HAND_CONTACT_DEPTH
    assert ends.others == set()


@pytest.mark.parametrize("robot", ["pr2", "boxy"])
def test_the_bowl_comes_from_its_drawer_with_the_hand_bounded(
    kitchen_transports: Transports, robot: str
) -> None:
    """The drawer's handle and the bowl are named in turn. The audit moves the drawer
    with the hand (each step's trajectory carries its joint), and a grasp roll that did
    not hold goes back by trajectories: the whole run is clean, the drawer's opening and
    closing included. The pick lifts the bowl out over the drawer's top (Boxy's first
    stand could not: its delivery then failed, every table stand blocked by the bowl
    hanging in the drawer)."""
    bottom, top = _bottom_and_drawer_top(robot)
    traced = kitchen_transports(robot, "bowl")
    report, ends, done = traced.report, traced.ends, traced.done
    rise = done.held.lifted.position[2] - done.held.grasp_pose.position[2]  # [m]
    assert bottom + rise >= top + LIFT_MARGIN - 1e-6
    assert report.clean, [f.line() for f in report.findings]
    assert not [f for f in report.of(FindingKind.ALLOWED_CONTACT_TOO_DEEP) if "bowl" in f.what]
    handle = {"kitchen/drawer_unit_drawer_3_handle"}
    assert {frozenset(n) for n in ends.named} == {frozenset(handle), frozenset({"bowl-1"})}
    assert max(d for d, n in zip(ends.depths, ends.named, strict=True) if n == {"bowl-1"}) <= (
        HAND_CONTACT_DEPTH
    )
    assert max(ends.depths) <= HAND_CONTACT_DEPTH
    assert ends.others == set()

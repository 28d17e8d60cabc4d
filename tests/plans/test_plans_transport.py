"""Transport in the kitchen: one plan, unchanged, on the PR2, the HSR and Boxy.

The mug goes from the north counter to the table; afterwards the KB says it rests on the
kitchen's table top and stays put when simulated, the arms are parked and any drawer the
search opened is closed again. On the PR2 and the HSR the bowl comes out of the top drawer
too. Each transport is the session's run, judged by other modules too
(``tests/kitchen_transports.py``).
"""

from __future__ import annotations

import math

import pytest

from robocram.world import World
from tests.kitchen_transports import SHARED, Transports

TABLE = ("kitchen", "table_top")
DRAWER_JOINT = "drawer_unit_drawer_3_joint"
pytestmark = SHARED  # its transports are other modules' too


def _on_the_table(world: World, item: str) -> None:
    """``item`` is supported by the table top: it touches the kitchen there and nowhere
    else, rests on the top face within its outline, is held by nobody, and the KB says it
    stays put when simulated.

    ``supported_by/3`` relates whole objects and the kitchen's bounds reach the ceiling,
    so the table top (a link) is checked by its contacts and bounds.
    """
    assert world.kb.holds("world(W), contact(W, O, kitchen)", O=item)
    assert world.kb.holds("world(W), stable(W, O)", O=item)
    touching = {p.link_b for p in world.contacts.contact_points(item, "kitchen")}
    assert touching == {"table_top"}
    low, high = world.aabb(item)
    table_low, table_high = world.contacts.link_aabb("kitchen", "table_top")
    assert low[2] == pytest.approx(table_high[2], abs=0.01)
    centre = ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2)
    assert table_low[0] < centre[0] < table_high[0] and table_low[1] < centre[1] < table_high[1]
    assert world.bodies.attached_to(item) is None


def _arms_parked(world: World, robot: str) -> None:
    desc = world.robot(robot).description
    joints = world.joint_states(robot)
    for name, arm in desc.arms.items():
        if name == desc.neck_arm:
            continue
        for joint, value in arm.parking.items():
            off = joints[joint] - value
            if desc.model.joints[joint].type == "continuous":  # one turn more is the same pose
                off = math.remainder(off, 2 * math.pi)
            assert off == pytest.approx(0.0, abs=0.01), (name, joint, joints[joint], value)


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_the_mug_goes_from_the_counter_to_the_table(
    kitchen_transports: Transports, robot: str
) -> None:
    run = kitchen_transports(robot, "mug")
    world, result = run.world, run.done
    assert result.object_name == "mug-1"
    _on_the_table(world, "mug-1")
    assert world.pose("mug-1").position[:2] == pytest.approx(result.spot.position[:2], abs=0.03)
    _arms_parked(world, run.robot)
    assert result.opened == []  # the mug stands on a counter: nothing to open
    assert world.joint_states("kitchen")[DRAWER_JOINT] == pytest.approx(0.0, abs=0.01)


@pytest.mark.parametrize("robot", ["pr2", "hsrb"])
def test_the_bowl_comes_out_of_the_drawer_to_the_table(
    kitchen_transports: Transports, robot: str
) -> None:
    """The HSR sees into the opened drawer from beside it, not from the handle stand (its
    camera too low over the drawer's front) nor from a metre away (over the drawer's side
    it saw 67 % of the bowl); its parking pose, hitting the head still turned down at the
    drawer with the lift up, is taken after it looks ahead."""
    run = kitchen_transports(robot, "bowl")
    world, result = run.world, run.done
    assert [o.container.link for o in result.opened] == ["drawer_unit_drawer_3"]
    assert [a.stage for a in result.log.attempts if a.succeeded] == [
        "open",
        "fetch",
        "deliver",
        "close",
    ]
    _on_the_table(world, "bowl-1")
    assert world.joint_states("kitchen")[DRAWER_JOINT] == pytest.approx(0.0, abs=0.01)
    _arms_parked(world, run.robot)

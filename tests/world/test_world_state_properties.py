"""Property test: any sequence of world operations inside ``stored_state`` is undone exactly.

Covers objects (by identity and kind, names reused inside the block), poses, joints and
the values they are held at, attachments, the robots' facts in ``world.kb`` and the clock.
``ROBOCRAM_PROPERTY_EXAMPLES=500 make test`` runs a longer, random search.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robocram.tf import Pose
from robocram.world import World, WorldError

EXAMPLES = int(os.environ.get("ROBOCRAM_PROPERTY_EXAMPLES", "15"))
NAMES = ("mug", "tray", "box", "hsrb")
Op = tuple[Any, ...]

positions = st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0), st.floats(0.05, 1.0)).map(
    lambda p: Pose(p)
)
operations = st.one_of(
    st.tuples(st.just("add"), st.sampled_from(NAMES), positions),
    st.tuples(st.just("remove"), st.sampled_from(NAMES)),
    st.tuples(st.just("replace"), st.sampled_from(NAMES), positions),  # a namesake
    st.tuples(st.just("pose"), st.sampled_from(NAMES), positions),
    st.tuples(st.just("simulate"), st.floats(0.0, 0.05)),
    st.tuples(st.just("attach"), st.sampled_from(NAMES), st.sampled_from(NAMES)),
    st.tuples(st.just("detach"), st.sampled_from(NAMES)),
    st.tuples(st.just("joints"), st.floats(-0.2, 0.8)),
)


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_robot("hsrb")
        w.add_item("mug", "mug", Pose((0.6, 0.0, 0.0)))
        w.add_box("tray", (0.3, 0.3, 0.02), Pose((0.6, 0.3, 0.5)), mass=0.5)
        w.attach("tray", "hsrb", "hand_palm_link")
        w.set_joint_states("hsrb", {"arm_lift_joint": 0.3})
        yield w


def _apply(world: World, op: Op) -> None:
    kind, *args = op
    if kind == "add" and args[0] == "hsrb":
        world.add_robot("hsrb", args[1])
    elif kind == "add":
        world.add_box(args[0], (0.1, 0.1, 0.1), args[1], mass=0.2)
    elif kind == "remove":
        world.remove(args[0])
    elif kind == "replace":
        world.remove(args[0])
        world.add_box(args[0], (0.1, 0.1, 0.1), args[1], mass=0.2)
    elif kind == "pose":
        world.set_pose(args[0], args[1])
    elif kind == "simulate":
        world.physics.simulate(args[0])
    elif kind == "attach":
        world.attach(args[0], args[1], world.link_names(args[1])[-1])
    elif kind == "detach":
        world.detach(args[0])
    else:
        world.set_joint_states("hsrb", {"arm_lift_joint": args[0]})


def _snapshot(world: World) -> dict[str, Any]:
    objects = {
        o.name: (
            id(o),
            o.type,
            world.pose(o).matrix(),
            world.joint_states(o),
            world.snapshots.held_joints(o),
        )
        for o in world.objects()
    }
    attachments = {
        (a.obj, a.robot, a.link): a.link_T_obj.matrix() for a in world.bodies.all_attachments()
    }
    facts = sorted(str(a["R"]) for a in world.kb.query("robot(R)"))
    return {
        "objects": objects,
        "attachments": attachments,
        "facts": facts,
        "time": world.physics.time,
    }


def _assert_same(before: dict[str, Any], after: dict[str, Any]) -> None:
    assert after["objects"].keys() == before["objects"].keys()
    for name, (ident, kind, pose, joints, held) in before["objects"].items():
        other = after["objects"][name]
        assert (other[0], other[1]) == (ident, kind), name  # the same handle, same kind
        assert np.allclose(other[2], pose, atol=1e-9), name
        assert other[3] == pytest.approx(joints, abs=1e-9) and other[4] == held, name
    assert after["attachments"].keys() == before["attachments"].keys()
    for key, rel in before["attachments"].items():
        assert np.allclose(after["attachments"][key], rel, atol=1e-9), key
    assert (after["facts"], after["time"]) == (before["facts"], before["time"])


@settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize="ROBOCRAM_PROPERTY_EXAMPLES" not in os.environ,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(ops=st.lists(operations, min_size=1, max_size=8))
def test_any_operations_inside_stored_state_are_undone(world: World, ops: list[Op]) -> None:
    before = _snapshot(world)
    with world.snapshots.stored_state():
        for op in ops:
            with contextlib.suppress(WorldError):  # refusals (unknown names, cycles) are typed
                _apply(world, op)
    _assert_same(before, _snapshot(world))

"""Every cache a world keeps answers as a fresh build would, whatever a plan changed.

Each case changes the PR2's kitchen in one way a plan can (a body moved, a joint set, an
object attached, carried, let go, added, removed or replaced, a snapshot restored, physics
stepped) after every cache was filled, and checks the world's change counters moved where
the change was and nowhere else. Then each cache's answer is compared with the same
question asked of a copy of the world (a new client, no cache) and, for obstacle bounds,
with PyBullet's own bounds of each link. Reading the world leaves every counter alone.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pybullet
import pytest

from robocram.motion.base_collision import BaseCollisionChecker
from robocram.motion.bullet_scene import CLEARANCE_REACH, BulletScene
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.obstacle_shapes import DRIFT, obstacle_cache
from robocram.motion.self_path_check import SelfPathCheck
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, UnknownObjectError, World

JOINTS = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip
AT_COUNTER = Pose((-1.12, 1.24, 0.0), quat.from_euler(0.0, 0.0, 1.88))  # facing the mug
PALM = "r_gripper_palm_link"
GOAL = (-1.0, 0.8)  # [m] a base goal near the counter, for the footprint's checker
COPY = 1e-9  # [m] a copy's bodies are placed again: Bullet keeps poses to about this
Answers = dict[str, object]


def _moved(world: World, name: str, dx: float = 0.0, dz: float = 0.0) -> None:
    pose = world.pose(name)
    x, y, z = pose.position
    world.set_pose(name, Pose((x + dx, y, z + dz), pose.orientation))


def _configurations(world: World) -> list[np.ndarray]:
    model = world.robot("pr2").description.model
    lows = [max(model.joints[j].lower, -2.5) for j in JOINTS]
    highs = [min(model.joints[j].upper, 2.5) for j in JOINTS]
    return list(np.random.default_rng(7).uniform(lows, highs, size=(4, len(JOINTS))))


def _answers(world: World) -> Answers:
    """Every cached question, asked of ``world`` (its caches) as they stand."""
    boxes = world.contacts.obstacle_boxes(["pr2"])
    found: Answers = {
        "boxes": {
            (o.name, n): (lo, hi)
            for o, n, lo, hi in zip(boxes.objects, boxes.names, boxes.low, boxes.high, strict=True)
        },
    }
    cache = obstacle_cache(world)
    for obj in world.objects():
        if obj.name != "pr2":
            shapes = cache.shapes(world, obj)
            found[f"shapes {obj.name}"] = (shapes.labels, shapes.centres, shapes.halves)
    coal = CoalClearance(BulletScene(RobotHandle.of(world, "pr2"), JOINTS))
    found["clearances"] = [coal.clearances(q) for q in _configurations(world)]
    check = SelfPathCheck.of(RobotHandle.of(world, "pr2"), JOINTS)
    found["self pairs"] = check.pairs  # levers bound travel with radii read once per body
    with BaseCollisionChecker.build(RobotHandle.of(world, "pr2"), GOAL) as checker:
        footprint = checker.footprint
        poses = np.array([[-1.12, 1.24, 1.88], [-1.0, 0.8, 0.0], [-1.3, 1.0, 3.0]])
        found["footprint"] = (footprint.points, footprint.masks, checker.fast_hits(poses, False))
    return found


def _assert_same(kept: object, fresh: object, where: str, tolerance: float) -> None:
    """``kept`` equals ``fresh``: keys and labels exactly, numbers within ``tolerance``."""
    if isinstance(kept, dict):
        assert isinstance(fresh, dict) and set(kept) <= set(fresh) | {"clearances"}, where
        if all(isinstance(v, float) for v in (*kept.values(), *fresh.values())):
            for key in set(kept) | set(fresh):  # a link may lie just at the reach
                mine, theirs = kept.get(key, CLEARANCE_REACH), fresh.get(key, CLEARANCE_REACH)
                assert mine == pytest.approx(theirs, abs=tolerance), (where, key)
            return
        assert set(kept) == set(fresh), (where, set(kept) ^ set(fresh))
        for key, value in kept.items():
            _assert_same(value, fresh[key], f"{where}/{key}", tolerance)
    elif isinstance(kept, (list, tuple)) and not isinstance(kept, str):
        assert isinstance(fresh, (list, tuple)) and len(kept) == len(fresh), where
        for k, (a, b) in enumerate(zip(kept, fresh, strict=True)):
            _assert_same(a, b, f"{where}[{k}]", tolerance)
    elif isinstance(kept, np.ndarray):
        assert isinstance(fresh, np.ndarray) and kept.shape == fresh.shape, where
        if kept.dtype.kind in "fc":
            np.testing.assert_allclose(kept, fresh, rtol=0, atol=tolerance, err_msg=where)
        else:
            assert np.array_equal(kept, fresh), where
    elif isinstance(kept, float):
        assert kept == pytest.approx(fresh, abs=tolerance), where
    else:
        assert kept == fresh, where


def _stamps(world: World) -> dict[str, object]:
    """Every counter of ``world``, by what it counts."""
    versions = world.versions
    found: dict[str, object] = {"structure": versions.structure}
    for obj in world.objects():
        found[f"created {obj.name}"] = versions.created(obj.name)
        found[f"pose {obj.name}"] = versions.pose(obj.name)
        found[f"joints {obj.name}"] = versions.joints(obj.name)
    return found


def _changed(before: dict[str, object], after: dict[str, object]) -> set[str]:
    return {k for k in before.keys() | after.keys() if before.get(k) != after.get(k)}


@dataclass(frozen=True)
class Case:
    """A change, what it needs done first, and the counters it must (and only may) move."""

    name: str
    prepare: Callable[[World], None]
    change: Callable[[World, Callable[[], object]], None]  # gets a refill of the caches
    moves: frozenset[str]  # counters that must change
    only: bool = True  # ... and no others


def _nothing(world: World) -> None:
    pass


def _attach(world: World) -> None:
    world.attach("mug-1", "pr2", PALM)


def _restore(world: World, refill: Callable[[], object]) -> None:
    with world.snapshots.stored_state():
        _moved(world, "mug-1", dx=0.2)
        world.remove("milk-1")
        world.add_box("crate", (0.3, 0.3, 0.3), Pose((-1.2, 0.6, 0.15)))
        world.set_joint_states("pr2", {"r_shoulder_pan_joint": -0.6})
        refill()  # the caches learn the visit; they must forget it on the way back


def _replace(world: World, refill: Callable[[], object]) -> None:
    pose = world.pose("mug-1")
    world.remove("mug-1")
    world.bodies.add_cylinder("mug-1", 0.15, 0.4, pose)  # the same name, a bigger body


CASES = [
    Case("move a body", _nothing, lambda w, _: _moved(w, "mug-1", dx=0.05),
         frozenset({"pose mug-1"})),
    Case("set a robot joint", _nothing,
         lambda w, _: w.set_joint_states("pr2", {"torso_lift_joint": 0.25}),
         frozenset({"joints pr2"})),
    Case("open a drawer", _nothing,
         lambda w, _: w.set_joint_states("kitchen", {"drawer_unit_drawer_1_joint": 0.2}),
         frozenset({"joints kitchen"})),
    Case("attach", _nothing, lambda w, _: _attach(w), frozenset({"structure"})),
    Case("carry", _attach,
         lambda w, _: w.set_joint_states("pr2", {"r_shoulder_pan_joint": -0.5}),
         frozenset({"joints pr2", "pose mug-1"})),
    Case("detach", _attach, lambda w, _: w.detach("mug-1"), frozenset({"structure"})),
    Case("add a body", _nothing,
         lambda w, _: w.add_box("crate", (0.3, 0.3, 0.3), Pose((-1.2, 0.6, 0.15))),
         frozenset({"structure", "created crate", "pose crate", "joints crate"})),
    Case("remove a body", _nothing, lambda w, _: w.remove("cereal-1"),
         frozenset({"structure", "created cereal-1", "pose cereal-1", "joints cereal-1"})),
    Case("replace a body", _nothing, _replace,
         frozenset({"structure", "created mug-1", "pose mug-1", "joints mug-1"})),
    Case("restore a snapshot", _nothing, _restore,
         frozenset({"structure", "created milk-1", "pose mug-1", "joints pr2"}), only=False),
    Case("step physics", lambda w: _moved(w, "mug-1", dz=0.05),
         lambda w, _: w.physics.simulate(0.2), frozenset({"pose mug-1", "joints kitchen"}),
         only=False),
]  # fmt: skip


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_every_cache_answers_as_a_fresh_build_after(case: Case) -> None:
    with kitchen_scene("pr2").world as world:
        world.set_pose("pr2", AT_COUNTER)
        case.prepare(world)
        _answers(world)  # every cache filled
        before = _stamps(world)
        case.change(world, lambda: _answers(world))
        changed = _changed(before, _stamps(world))
        assert case.moves <= changed, case.moves - changed
        if case.only:
            assert changed == case.moves, changed - case.moves
        kept = _answers(world)
        _assert_same_as_pybullet(world)
        _assert_radii_hold_the_links(world)
        with world.copy() as fresh:
            # the coal shapes are kept while a body drifts less than DRIFT by design
            _assert_same(kept, _answers(fresh), case.name, DRIFT + COPY)


def _assert_same_as_pybullet(world: World) -> None:
    """The kept obstacle bounds are PyBullet's bounds of each link, to the bit."""
    boxes = world.contacts.obstacle_boxes(["pr2"])
    cid = world.physics.client()
    for obj, index, low, high in zip(
        boxes.objects, boxes.indices, boxes.low, boxes.high, strict=True
    ):
        raw = pybullet.getAABB(*obj.locate(index), physicsClientId=cid)
        assert tuple(low) == tuple(raw[0]) and tuple(high) == tuple(raw[1]), (obj.name, index)


def _assert_radii_hold_the_links(world: World) -> None:
    """Each kept link radius (taken once per body, at whatever pose it stood) holds the
    link's shapes now: their bounds, as PyBullet reads them, lie within it."""
    cid = world.physics.client()
    for obj in world.objects():
        radii = world.contacts.link_radii(obj)
        for link in world.link_names(obj):
            index = obj.link_index[link]
            if index not in obj.colliders or link in obj.link_offset:
                continue  # no shapes, or a frame added in code (not at its host's origin)
            origin = np.array(world.link_pose(obj, link).position)
            low, high = pybullet.getAABB(*obj.locate(index), physicsClientId=cid)
            assert (np.array(low) >= origin - radii[link] - COPY).all(), (obj.name, link)
            assert (np.array(high) <= origin + radii[link] + COPY).all(), (obj.name, link)


def test_reading_leaves_every_counter_alone() -> None:
    with kitchen_scene("pr2").world as world:
        world.set_pose("pr2", AT_COUNTER)
        world.attach("mug-1", "pr2", PALM)
        before, tick = _stamps(world), world.versions.tick
        for obj in world.objects():
            world.pose(obj)
            world.joint_states(obj)
            world.snapshots.body_state(obj)
            world.aabb(obj)
            world.contacts.link_aabbs(obj)
            world.contacts.link_radii(obj)
            world.snapshots.held_joints(obj)
            world.bodies.link_frames(obj, world.link_names(obj)[:3])
        world.link_pose("pr2", PALM)
        world.contacts.collisions("pr2")
        world.contacts.link_distances("pr2", distance=0.05)
        world.contacts.contact_points("mug-1")
        world.contacts.obstacle_boxes(["pr2"])
        world.view.ray_cast((-1.12, 1.24, 1.5), (-1.12, 1.24, -0.1))
        world.bodies.attachments("pr2")
        world.kb.first("robot(R)")
        CoalClearance(BulletScene(RobotHandle.of(world, "pr2"), JOINTS)).clearances(
            _configurations(world)[0]
        )
        SelfPathCheck.of(RobotHandle.of(world, "pr2"), JOINTS)
        assert _stamps(world) == before
        assert world.versions.tick == tick


def test_a_counter_of_a_body_not_in_the_world_is_a_typed_error() -> None:
    with World() as world:
        box = world.add_box("box", (0.1, 0.1, 0.1))
        assert world.versions.body(box) == world.versions.body("box")  # a handle or a name
        with pytest.raises(UnknownObjectError, match="no object 'bx'.*'box'"):
            world.versions.pose("bx")

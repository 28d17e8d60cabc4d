"""Link distances and contacts on a kept obstacle table (a walk's queries, one loop)
equal raw PyBullet's closest points, pair for pair, and follow what moves.

:func:`robocram.world.link_contacts.link_distances` answers a query the table covers in
one loop instead of the general generators. Here its answers are compared with raw
PyBullet (every pair of a robot link and another body's link asked directly, the least
distance per pair) and with the general path (no table: Bullet's broadphase); after the
mug is put against the gripper, the new table's answer has it, at its new distance.
"""

from __future__ import annotations

import pybullet

from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import World
from robocram.world.link_contacts import link_pairs_in_contact

REACH = 0.1  # [m] as a walk's clearance queries ask
HAND = (
    "r_gripper_palm_link", "r_gripper_l_finger_link", "r_gripper_r_finger_link",
    "r_gripper_l_finger_tip_link", "r_gripper_r_finger_tip_link", "r_forearm_link",
    "r_wrist_flex_link", "r_wrist_roll_link",
)  # fmt: skip


def _raw(world: World, links: tuple[str, ...]) -> dict[tuple[str, str, str], float]:
    """Per (robot link, other, other's link) within REACH: the least distance, from
    PyBullet asked pair by pair (no bounds, no table)."""
    cid = world.physics.client()
    robot = world.object("pr2")
    found: dict[tuple[str, str, str], float] = {}
    for other in world.objects():
        if other.name in ("pr2", "floor"):
            continue
        names = {i: n for n, i in other.link_index.items()}
        for link in links:
            points = pybullet.getClosestPoints(
                robot.body_id, other.body_id, REACH, linkIndexA=robot.link_index[link],
                physicsClientId=cid,
            )  # fmt: skip
            for p in points or ():
                key = (link, other.name, names.get(p[4], other.name))
                found[key] = min(found.get(key, REACH), float(p[8]))
    return found


def _asked(world: World, table: bool) -> dict[tuple[str, str, str], float]:
    obstacles = world.contacts.obstacle_boxes(["pr2", "floor"]) if table else None
    answer = world.contacts.link_distances("pr2", ["floor"], REACH, HAND, obstacles)
    return {(link, obj.name, other): gap for link, obj, other, gap in answer}


def _gripper_at_table(world: World) -> None:
    world.set_joint_states(
        "pr2",
        {"torso_lift_joint": 0.1, "r_shoulder_lift_joint": 0.45, "r_elbow_flex_joint": -0.6,
         "r_wrist_flex_joint": -0.8},
    )  # fmt: skip


def _mug_ahead(world: World, ahead: float) -> None:
    """The mug ``ahead`` [m] in front of the right palm, a little lower."""
    palm = world.link_pose("pr2", "r_gripper_palm_link").position
    world.set_pose("mug-1", Pose((palm[0] + ahead, palm[1], palm[2] - 0.05)))


def test_table_answers_are_raw_pybullets_and_the_general_paths() -> None:
    world = tabletop_scene("pr2").world
    _gripper_at_table(world)
    _mug_ahead(world, 0.16)
    raw = _raw(world, HAND)
    assert len(raw) >= 3, raw  # fingers and palm near the mug
    kept = _asked(world, table=True)
    assert kept == _asked(world, table=False)  # the same pairs and distances, to the bit
    assert set(kept) == {k for k, gap in raw.items() if gap < REACH}
    for key, gap in kept.items():
        assert gap == raw[key]  # the same query, the same float
    world.close()


def test_a_moved_mug_is_seen_at_its_new_distance() -> None:
    world = tabletop_scene("pr2").world
    _gripper_at_table(world)
    _mug_ahead(world, 0.6)
    before = _asked(world, table=True)
    assert not any(k[1] == "mug-1" for k in before)
    _mug_ahead(world, 0.16)
    after = _asked(world, table=True)
    assert after != before
    mug = {k: v for k, v in after.items() if k[1] == "mug-1"}
    assert mug and mug == {k: v for k, v in _raw(world, HAND).items() if k[1] == "mug-1"}
    assert after == _asked(world, table=False)
    world.close()


def test_pairs_in_contact_on_a_table_are_the_general_paths_and_raw_pybullets() -> None:
    """``link_pairs_in_contact`` on a kept table: the general path's triples in its order,
    and raw PyBullet's pairs nearer than the distance; the mug moved away is gone."""
    world = tabletop_scene("pr2").world
    _gripper_at_table(world)
    _mug_ahead(world, 0.1)  # the fingers in the mug
    robot, floor = world.object("pr2"), world.object("floor")
    for distance in (0.0, 0.03):
        table = world.contacts.obstacle_boxes(["pr2", "floor"])
        kept = link_pairs_in_contact(world, robot, [floor], distance, HAND, table)
        general = link_pairs_in_contact(world, robot, [floor], distance, HAND)
        assert [(a, o.name, b) for a, o, b in kept] == [(a, o.name, b) for a, o, b in general]
        raw = {k for k, gap in _raw(world, HAND).items() if gap <= distance}
        assert {(a, o.name, b) for a, o, b in kept} == raw and raw
    _mug_ahead(world, 0.6)
    table = world.contacts.obstacle_boxes(["pr2", "floor"])
    assert not any(
        o.name == "mug-1"
        for _, o, _ in link_pairs_in_contact(world, robot, [floor], 0.0, HAND, table)
    )
    world.close()

"""A segment's travel bound from its start's levers holds every point's path.

:func:`start_travel` bounds, per link that can collide (and the mug the hand holds), how
far a point within the link's radius of its frame moves along a straight joint-space
segment, from the levers where the segment starts. Here points fixed on those balls
(every collision vertex lies inside: the radius holds the shapes) are moved along
sampled segments in fine steps, their frames read from raw PyBullet, and the length of
each point's path must never exceed the link's bound. Small segments like a handle
step's (the joints partly undoing each other) must come out far tighter than the rigid
levers' sum, which is what lets the dense check take fewer configurations.
"""

from __future__ import annotations

import numpy as np
import pybullet
import pytest

from robocram.motion import segment_check
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.link_radii import shape_radii
from robocram.motion.segment_check import CheckCounter, segment_free, start_travel
from robocram.motion.travel_bound import TravelBound, link_radii
from robocram.scenes import tabletop_scene
from robocram.world import RobotHandle, World

JOINTS = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip
FINE = 200  # steps along a segment at which the points' positions are read
ROUNDING = 1e-7  # [m] a path summed over FINE reads of PyBullet's frames
SMALL = 0.06  # [rad | m] spread of a small segment's joint changes (a handle step's)


def _frames(world: World, links: list[str]) -> np.ndarray:
    """(links, 7): each link's URDF frame (position, quaternion) from raw PyBullet."""
    robot = world.object("pr2")
    cid = world.physics.client()
    states = [
        pybullet.getLinkState(
            robot.body_id, robot.link_index[link], computeForwardKinematics=True,
            physicsClientId=cid,
        )
        for link in links
    ]  # fmt: skip
    return np.array([(*st[4], *st[5]) for st in states])


def _ball_points(frames: np.ndarray, radii: np.ndarray, directions: np.ndarray) -> np.ndarray:
    """(links, points, 3): points fixed in each frame, on the ball of its link's radius."""
    q, w = frames[:, None, 3:6], frames[:, None, 6:7]
    v = directions[None, :, :] * radii[:, None, None]
    t = 2.0 * np.cross(q, v)
    return frames[:, None, :3] + v + w * t + np.cross(q, t)


def _segment(rng: np.random.Generator, world: World, small: bool) -> tuple[np.ndarray, ...]:
    """A seeded segment within the joints' limits: small (a handle step's size) or not."""
    model = world.robot("pr2").description.model
    lows = np.array([max(model.joints[j].lower, -2.5) for j in JOINTS])
    highs = np.array([min(model.joints[j].upper, 2.5) for j in JOINTS])
    qa = rng.uniform(lows, highs)
    spread = (SMALL if small else 0.5) * np.array([0.2] + [1.0] * (len(JOINTS) - 1))  # torso [m]
    qb = np.clip(qa + rng.normal(0.0, 1.0, len(JOINTS)) * spread, lows, highs)
    return qa, qb


@pytest.mark.parametrize("seed", range(3))
def test_no_point_travels_further_than_its_start_bound(seed: int) -> None:
    world = tabletop_scene("pr2").world
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    robot = RobotHandle.of(world, "pr2")
    scene = BulletScene(robot, JOINTS)
    bound = TravelBound.of(robot, JOINTS)
    links = scene.lever_links()
    assert "mug-1" in links
    carriers = world.bodies.attachments("pr2")
    frame_links = [carriers.get(link, link) for link in links]
    radius = link_radii(robot)
    radii = np.array([radius[carriers.get(link, link)] for link in links])
    exact = shape_radii(robot.description.model)
    assert all(exact[link] <= radius[link] + 1e-9 for link in links if link in exact)
    rng = np.random.default_rng(400 + seed)
    directions = rng.normal(size=(48, 3))
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    ratios, tightness = [], 0.0
    with scene.posed():
        for k in range(6):
            qa, qb = _segment(rng, world, small=k < 4)
            scene.clearances(qa)  # posed at the segment's start
            by_link: dict[str, float] = {}
            most = start_travel(scene, qa, qb, bound, by_link)
            before = _ball_points(_frames(world, frame_links), radii, directions)
            lengths = np.zeros((len(links), len(directions)))  # each point's path so far
            for t in np.linspace(0.0, 1.0, FINE + 1)[1:]:
                scene.clearances(qa + (qb - qa) * t)
                now = _ball_points(_frames(world, frame_links), radii, directions)
                lengths += np.linalg.norm(now - before, axis=2)
                before = now
            path = lengths.max(axis=1)  # [m] per link: its longest point path
            bounds = np.array([by_link[link] for link in links])
            worst = int((path - bounds).argmax())  # the sums carry PyBullet's rounding
            assert path[worst] <= bounds[worst] + ROUNDING, (
                links[worst],
                path[worst],
                bounds[worst],
                k,
            )
            assert most == pytest.approx(bounds.max())
            assert most <= bound.travel(qa, qb) + 1e-12  # never looser than the rigid bound
            tightness = max(tightness, float((path / bounds).max()))
            if k < 4:
                ratios.append(most / bound.travel(qa, qb))
    assert tightness > 0.5  # the bound is not slack: some point comes near it
    assert float(np.median(ratios)) < 0.75  # small segments: tighter than the rigid sum
    world.close()


def test_small_steps_near_the_table_take_fewer_checks(monkeypatch: pytest.MonkeyPatch) -> None:
    """Small arm steps with the arm near the table: the walk's verdict is the dense
    check's, in fewer configurations than with the rigid bound alone."""
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    scene = BulletScene(robot, JOINTS)
    bound = TravelBound.of(robot, JOINTS)
    rng = np.random.default_rng(11)
    tight = rigid = walked = 0
    for _ in range(60):
        qa, qb = _segment(rng, world, small=True)
        if not (scene.is_free(qa) and scene.is_free(qb)):
            continue
        with scene.posed():
            gap = scene.clearance(qa)
        if gap >= scene.reach:
            continue  # far from everything: one check decides either way
        dense = all(scene.is_free(qa + (qb - qa) * t) for t in np.linspace(0.0, 1.0, 200))
        counter = CheckCounter()
        assert segment_free(scene, qa, qb, bound, counter) == dense
        tight += counter.checks
        with monkeypatch.context() as patch:  # the rigid bound alone, as before
            patch.setattr(segment_check, "start_travel", lambda c, a, b, tb, kept: tb.travel(a, b))
            counter = CheckCounter()
            assert segment_free(scene, qa, qb, bound, counter) == dense
            rigid += counter.checks
        walked += 1
    assert walked >= 3
    assert tight < 0.7 * rigid
    world.close()

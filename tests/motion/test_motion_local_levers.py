"""Conservative advancement's tighter steps never let a point outrun its clearance.

The speed of each link where the robot stands (its frame's speed plus its angular speed
times its radius, for the segment's joint motion) and the growth term bound how far any
point within its radius of each link's frame moves over a step; here points on those
balls, fixed in their links, are moved through each step in fine increments and must
stay within that bound (dropping the growth term makes this fail).
"""

from __future__ import annotations

import numpy as np
import pytest

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.clearance_pairs import NearPairs
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.segment_check import (
    CheckCounter,
    _LocalSteps,
    _quadratic_step,
    segment_free,
)
from robocram.motion.travel_bound import TravelBound, link_radii
from robocram.scenes import tabletop_scene
from robocram.world import RobotHandle, World

JOINTS = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip


def _ball_points(
    world: World, links: tuple[str, ...], radii: np.ndarray, directions: np.ndarray
) -> np.ndarray:
    """(links, points, 3): points fixed in each link, on the ball of its radius [m]."""
    frames = np.array(world.bodies.link_frames("pr2", links))
    q, w = frames[:, None, 3:6], frames[:, None, 6:7]
    v = directions[None, :, :] * radii[:, None, None]
    t = 2.0 * np.cross(q, v)
    return frames[:, None, :3] + v + w * t + np.cross(q, t)


def _random_configuration(rng: np.random.Generator, scene: BulletScene) -> np.ndarray:
    model = scene.world.robot("pr2").description.model
    lows = [max(model.joints[j].lower, -2.5) for j in JOINTS]
    highs = [min(model.joints[j].upper, 2.5) for j in JOINTS]
    return rng.uniform(lows, highs)


@pytest.mark.parametrize("seed", range(6))
def test_no_link_frame_moves_further_than_the_step_bound(seed: int) -> None:
    scene, rng, bound, links, radii, directions = _lever_case(seed)
    world = scene.world
    qa, qb = _random_configuration(rng, scene), _random_configuration(rng, scene)
    tight = 0.0
    with scene.posed():
        steps = _LocalSteps.of(scene, qa, qb)
        for s in rng.uniform(0.0, 0.9, 4):
            gap = float(rng.uniform(0.02, 0.3))
            scene.clearances(qa + (qb - qa) * s)
            ds = steps.step({}, gap)  # every link clear by ``gap``
            start = _ball_points(world, links, radii, directions)
            moved = np.zeros(len(links))
            for t in np.linspace(0.0, ds, 25)[1:]:
                scene.clearances(qa + (qb - qa) * min(1.0, s + t))
                now = _ball_points(world, links, radii, directions)
                moved = np.maximum(moved, np.linalg.norm(now - start, axis=2).max(axis=1))
            assert moved.max() <= gap + 1e-9, (links[int(moved.argmax())], moved.max(), gap)
            tight = max(tight, float(moved.max() / gap))
            assert ds > 0.0
    assert tight > 0.3  # the bound is not slack: some point comes near it
    world.close()


@pytest.mark.parametrize("seed", range(6))
def test_no_point_moves_further_than_the_vector_bound(seed: int) -> None:
    """The bound that adds the joints' motions as vectors, alone: ``V ds + G ds^2 / 2``
    (dropping ``G`` makes this fail)."""
    scene, rng, bound, links, radii, directions = _lever_case(100 + seed)
    world = scene.world
    tight = 0.0
    with scene.posed():
        for _ in range(3):
            qa, qb = _random_configuration(rng, scene), _random_configuration(rng, scene)
            steps = _LocalSteps.of(scene, qa, qb)
            s = float(rng.uniform(0.0, 0.5))
            gap = float(rng.uniform(0.1, 0.4))
            scene.clearances(qa + (qb - qa) * s)
            vector = scene.link_speeds(links, qb - qa)
            ds = _quadratic_step(vector, steps.turn / 2, np.full(len(links), gap))
            start = _ball_points(world, links, radii, directions)
            moved = np.zeros(len(links))
            for t in np.linspace(0.0, float(ds.max()), 40)[1:]:
                scene.clearances(qa + (qb - qa) * (s + t))
                now = _ball_points(world, links, radii, directions)
                within = t <= ds + 1e-12  # each link, over its own step
                reached = np.linalg.norm(now - start, axis=2).max(axis=1)
                moved = np.where(within, np.maximum(moved, reached), moved)
            assert moved.max() <= gap + 1e-6, (links[int(moved.argmax())], moved.max(), gap)
            tight = max(tight, float(moved.max() / gap))
    assert tight > 0.5
    world.close()


@pytest.mark.parametrize("seed", range(3))
def test_the_speed_bound_grows_no_faster_than_the_growth_term(seed: int) -> None:
    """``G`` bounds how fast ``V`` (a link's speed bound) changes along the segment: for
    any two configurations of it, ``V`` at the later one is at most ``V`` at the earlier
    one plus ``G`` times the fraction between (what a step relies on), holding the mug
    (whose radius rides on the wrist)."""
    world = tabletop_scene("pr2").world
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    checker = CoalClearance(BulletScene(RobotHandle.of(world, "pr2"), JOINTS))
    rng = np.random.default_rng(200 + seed)
    fractions = np.linspace(0.0, 1.0, 101)
    tight = 0.0
    for _ in range(6):
        qa = _random_configuration(rng, checker.judge)
        qb = _random_configuration(rng, checker.judge)
        steps = _LocalSteps.of(checker, qa, qb)
        assert "mug-1" in steps.links
        speeds = []
        for s in fractions:
            checker.clearances(qa + (qb - qa) * s)
            speeds.append(checker.link_speeds(steps.links, qb - qa))
        speed = np.array(speeds)  # (fractions, links)
        for k in range(1, len(fractions)):
            ds = fractions[k] - fractions[:k]  # from every earlier configuration
            growth = speed[k][None, :] - speed[:k]
            assert (growth <= steps.turn[None, :] * ds[:, None] + 1e-9).all()
            moving = steps.turn > 0.0
            ratio = growth[:, moving] / (steps.turn[moving] * ds[:, None])
            tight = max(tight, float(ratio.max()))
    assert tight > 0.05  # the bound is not vacuous
    world.close()


def test_local_steps_agree_with_the_rigid_ones_on_what_is_free() -> None:
    world = tabletop_scene("pr2").world
    scene = BulletScene(RobotHandle.of(world, "pr2"), JOINTS)
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), JOINTS)
    rng = np.random.default_rng(7)
    verdicts = []
    for _ in range(8):
        qa, qb = _random_configuration(rng, scene), _random_configuration(rng, scene)
        if not (scene.is_free(qa) and scene.is_free(qb)):
            continue
        local = segment_free(scene, qa, qb, bound, CheckCounter())
        dense = all(scene.is_free(qa + (qb - qa) * t) for t in np.linspace(0, 1, 400))
        verdicts.append((local, dense))
        if dense:
            assert local  # a free segment is never refused
    assert len(verdicts) >= 3
    world.close()


def test_one_arm_sweeps_while_the_other_holds_something() -> None:
    """What the other hand holds does not move with this arm: its levers are not asked
    for (a KeyError on the right wrist once ended a left-arm motion)."""
    world = tabletop_scene("pr2").world
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    left = tuple(j.replace("r_", "l_", 1) for j in JOINTS[1:])
    scene = BulletScene(RobotHandle.of(world, "pr2"), left)
    assert "mug-1" not in scene.lever_links()
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), left)
    qa = np.array([world.joint_states("pr2")[j] for j in left])
    qb = qa + np.array([0.6, 0.3, 0.5, -0.4, 1.0, -0.3, 1.5])
    assert bound.travel(qa, qb) > 1.0  # long enough for the local levers
    segment_free(scene, qa, qb, bound, CheckCounter())  # answers, whatever it answers
    world.close()


class _Counted:
    """Near labels that remember which of them were measured."""

    def __init__(self, near: NearPairs) -> None:
        self.names, self.bounds, self._near = near.names, near.bounds, near
        self.asked: set[int] = set()

    def gap(self, k: int) -> float:
        self.asked.add(k)
        return self._near.gap(k)


def _lever_case(
    seed: int,
) -> tuple[BulletScene, np.random.Generator, TravelBound, tuple[str, ...], np.ndarray, np.ndarray]:
    """A PR2 tabletop checker, a seeded generator, the travel bound, the moving links with
    their radii and 64 unit directions to probe points on their balls."""
    world = tabletop_scene("pr2").world
    scene = BulletScene(RobotHandle.of(world, "pr2"), JOINTS)
    rng = np.random.default_rng(seed)
    links = scene.lever_links()
    radii = np.array([link_radii(RobotHandle.of(world, "pr2")).get(link, 0.0) for link in links])
    directions = rng.normal(size=(64, 3))
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    return (
        scene,
        rng,
        TravelBound.of(RobotHandle.of(world, "pr2"), JOINTS),
        links,
        radii,
        directions,
    )


@pytest.mark.parametrize("seed", range(3))
def test_a_step_from_bounds_equals_the_step_from_every_gap(seed: int) -> None:
    """Measuring only the labels whose bound can limit the step gives the step measuring
    all of them gives, to the bit, and the same "touching" verdict, at configurations
    near the table and the held mug's (about 200 checks per seed)."""
    world = tabletop_scene("pr2").world
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    checker = CoalClearance(BulletScene(RobotHandle.of(world, "pr2"), JOINTS))
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), JOINTS)
    rng = np.random.default_rng(300 + seed)
    measured = labelled = 0
    for _ in range(20):
        qa = _random_configuration(rng, checker.judge)
        qb = _random_configuration(rng, checker.judge)
        steps = _LocalSteps.of(checker, qa, qb)
        for s in np.linspace(0.0, 1.0, 10):
            q = qa + (qb - qa) * s
            gaps = checker.clearances(q)
            expected = steps.step(gaps, checker.reach, bound.max_link_travel)
            near = _Counted(checker.near(q))
            step, touching = steps.bounded_step(near, checker.reach, bound.max_link_travel)
            assert step == expected
            assert touching == (min(gaps.values(), default=1.0) <= 0.0)
            measured += len(near.asked)
            labelled += len(near.names)
    assert measured < labelled  # some labels were never measured
    world.close()

"""A judged transport plans what a plain one does, to the bit.

The judge sets the world to every sample of each trajectory and puts it back through a
snapshot. PyBullet reads a base a last bit off what was written, so a snapshot that wrote
back what it read moved the robot by that bit, and the HSR's judged kitchen mug transport
took other stands than its plain run. The session's HSR mug run (``tests/kitchen_transports.py``:
traced, judged, its joints ledgered and its hand's ends watched) is compared with a plain
run: each trajectory, the joints, the robot's pose and every object's pose when it is
reported, read raw from PyBullet, bit for bit. So the tests judging the session's runs
judge what a plain run does.
"""

from __future__ import annotations

import pytest

from robocram.designators import a
from robocram.motion import JointTrajectory, TrajectoryPoint, trajectory_listener
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from tests.kitchen_transports import SHARED, TABLE, Kept, Transports
from tests.projection.raw_world import RawRecord, Seen

pytestmark = SHARED  # the session's kitchen transports: one worker runs their modules


def _plain(robot: str) -> list[Seen]:
    scene = kitchen_scene(robot)
    world = scene.world
    record = RawRecord(world)
    try:
        with trajectory_listener(record), simulated_robot(world, scene.robot):
            transport("mug", a.location(on=TABLE, for_="mug-1"))
        record.end()
    finally:
        world.close()
    return record.seen


def test_the_hsr_judged_mug_transport_plans_as_its_plain_run(
    kitchen_transports: Transports,
) -> None:
    shared = kitchen_transports("hsrb", "mug")
    assert shared.judged is not None and shared.ledger is not None and shared.store is not None
    assert shared.raw is not None
    judged = shared.raw.seen
    plain = _plain("hsrb")
    assert len(plain) > 10
    assert [s[:2] for s in judged] == [s[:2] for s in plain]
    for i, (p, j) in enumerate(zip(plain, judged, strict=True)):
        assert j[2] == p[2], f"trajectory {i} ({p[0]}) differs"
        assert j[3] == p[3], f"the world differs when trajectory {i} ({p[0]}) is reported"


def test_a_watchers_failure_in_a_shared_run_is_kept_and_fails_the_test_asking() -> None:
    """A shared run's judge does not stop the run at its first finding (the run is other
    modules' too): it keeps it, and a test asking for the judge fails naming it."""
    up = TrajectoryPoint((0.1,), (0.0,), (0.0,), 0.0)  # [m]
    lift = JointTrajectory("pr2", ("torso_lift_joint",), (up,), kind="torso")

    def judge(trajectory: JointTrajectory) -> None:
        assert trajectory.end["torso_lift_joint"] < 0.05, "the torso hits the shelf"

    kept = Kept(judge)
    kept(lift)  # the run goes on
    assert len(kept.failures) == 1 and "the torso hits the shelf" in kept.failures[0]
    with pytest.raises(AssertionError, match="the torso hits the shelf"):
        kept.found_nothing()
    assert Kept(judge).found_nothing() is judge  # nothing found: the judge itself

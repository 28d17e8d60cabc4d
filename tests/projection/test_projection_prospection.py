"""Prospection (issue 41): projecting a plan tells what it would do and leaves the world
exactly as it was; performing the chosen plan afterwards does what the prospect showed."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import PlanFailure
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.projection.prospection import prospect
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.world import RobotHandle, World

TABLE = ("kitchen", "table_top")


@pytest.fixture()
def kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def _bodies(world: World) -> tuple[object, ...]:
    """Every body's pose, velocities and joints, attachments and held joints, exactly."""
    state = world.snapshots.capture()
    return (tuple(h.name for h in state.handles), state.bodies, state.attachments, state.holds)


def _mug_transport() -> object:
    return transport("mug", a.location(on=TABLE, for_="mug-1"))


def _same(first: list[JointTrajectory], second: list[JointTrajectory]) -> bool:
    return len(first) == len(second) and all(
        a.joint_names == b.joint_names
        and np.array_equal(a.positions(), b.positions())
        and np.array_equal(a.times(), b.times())
        for a, b in zip(first, second, strict=True)
    )


def test_a_prospect_leaves_the_world_as_it_was_and_performing_does_what_it_showed(
    kitchen: KitchenScene,
) -> None:
    world = kitchen.world
    before = _bodies(world)
    seen = prospect(RobotHandle.of(world, kitchen.robot), _mug_transport)
    assert seen.succeeded and seen.failure is None
    assert _bodies(world) == before  # byte for byte: poses, velocities, joints, attachments
    table_z = world.link_pose("kitchen", "table_top").position[2]
    assert seen.poses["mug-1"].position[2] > table_z  # the mug would end on the table
    assert world.pose("mug-1").position[2] > table_z + 0.1  # and it is still on the counter
    assert len(seen.trajectories) > 10 and seen.motion_time > 5.0
    done: list[JointTrajectory] = []
    with trajectory_listener(done.append), simulated_robot(world, kitchen.robot):
        _mug_transport()
    assert _same(list(seen.trajectories), done)
    assert world.pose("mug-1").distance_to(seen.poses["mug-1"]) < 1e-9


def test_a_plan_can_prospect_inside_its_run_unheard_by_its_listeners(
    kitchen: KitchenScene,
) -> None:
    world = kitchen.world
    heard: list[JointTrajectory] = []
    with trajectory_listener(heard.append), simulated_robot(world, kitchen.robot) as run:
        perform(a.motion(type="moving-torso", joint_angle=0.1))
        before, count = _bodies(world), len(heard)
        seen = prospect(RobotHandle.of(world, kitchen.robot), _mug_transport)
        assert _bodies(world) == before and len(heard) == count  # nothing moved, nothing heard
        perform(a.motion(type="moving-torso", joint_angle=0.2))  # the run goes on
    assert seen.succeeded and seen.tree.root.name == "prospection"
    assert world.joint_states(kitchen.robot)["torso_lift_joint"] == pytest.approx(0.2, abs=1e-6)
    names = [t.name for t in run.tree.tasks()]  # the prospect's tasks are in its own tree
    assert names == ["simulated-robot", "perform moving-torso", "perform moving-torso#2"]


def test_a_failing_plan_is_the_prospects_outcome(kitchen: KitchenScene) -> None:
    world = kitchen.world
    before = _bodies(world)
    seen = prospect(
        RobotHandle.of(world, kitchen.robot),
        lambda: perform(a.motion(type="moving-torso", joint_angle=5.0)),
    )
    assert not seen.succeeded and isinstance(seen.failure, PlanFailure)
    assert "torso" in str(seen.failure)
    assert seen.result is None and _bodies(world) == before


def test_the_example_chooses_by_prospecting_and_performs_its_choice(
    capsys: pytest.CaptureFixture[str],
) -> None:
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "examples" / "prospect_placing.py"
    spec = importlib.util.spec_from_file_location("prospect_placing", path)
    assert spec is not None and spec.loader is not None
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    chosen = example.main()
    printed = capsys.readouterr().out
    assert chosen in example.PLACES
    assert f"performed: the mug to the {chosen}" in printed
    assert printed.count("succeeds") == 2

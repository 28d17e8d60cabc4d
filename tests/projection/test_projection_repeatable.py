"""Projection is repeatable: the same plan, world and seed give bit-identical joints and
poses whether the machine is idle or busy (IK budgets are counted, never timed)."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager

import pytest

from robocram.kinematics import IKOptions, IKResult, forward_kinematics, solve_ik
from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene

BUSY_SECONDS = 120  # [s] a burner's own bound, should the test be interrupted before its kill
BURNER = f"import time\nend = time.monotonic() + {BUSY_SECONDS}\nwhile time.monotonic() < end: pass"

Snapshot = tuple[dict[str, float], dict[str, object], tuple[object, ...]]


def _project(robot: str) -> Snapshot:
    """Run the pick-up plan in a fresh tabletop scene; return every joint and pose after."""
    scene = tabletop_scene(robot)
    world = scene.world
    with simulated_robot(world, robot):
        result = pick_up(scene.look_target)
    poses = {o.name: world.pose(o.name) for o in world.objects()}
    reached = (result.arm, result.grasp, result.lifted, result.detected.get("pose"))
    return world.joint_states(robot), poses, reached


@contextmanager
def _busy_machine(processes: int = 2) -> Iterator[None]:
    """Keep ``processes`` CPU burners running, each killed when the block ends."""
    burners = [subprocess.Popen([sys.executable, "-c", BURNER]) for _ in range(processes)]
    try:
        yield
    finally:
        for burner in burners:
            burner.kill()
            burner.wait()


def _unreachable_without_torso() -> IKResult:
    """The HSR's hand at a pose only a raised arm lift reaches: every descent fails, so
    the answer is the best of the whole budget, the part a clock used to cut short."""
    target = forward_kinematics("hsrb", {"arm_lift_joint": 0.3}, "hand_tool_frame")
    return solve_ik(
        "hsrb", "arm", target, seed={"arm_lift_joint": 0.0}, options=IKOptions(random_seed=7)
    )


@pytest.mark.parametrize("robot", ["hsrb", "pr2"])
def test_pick_up_is_bit_identical_under_load(robot: str) -> None:
    idle = _project(robot)
    with _busy_machine():
        loaded = _project(robot)
    joints, poses, reached = loaded
    assert joints == idle[0]  # exact float equality, every joint
    assert poses == idle[1]
    assert reached == idle[2]
    assert len(joints) > 10 and "mug-1" in poses


def test_failed_ik_spends_the_same_budget_under_load() -> None:
    idle = _unreachable_without_torso()
    with _busy_machine():
        loaded = _unreachable_without_torso()
    assert not idle.success and not loaded.success
    assert loaded.joint_positions == idle.joint_positions
    assert (loaded.iterations, loaded.restarts) == (idle.iterations, idle.restarts)
    assert loaded.position_error == idle.position_error > 0.2

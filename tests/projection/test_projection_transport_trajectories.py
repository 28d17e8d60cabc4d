"""The kitchen transport on the PR2, the HSR and Boxy moves only along collision-free paths.

Each trajectory is judged the moment projection reports it, in the world as it is then
(drawers as the search left them, the mug in the hand), by PyBullet, independently of the
planner (``trajectory_judge.py``), held objects included. The going test leaves the top
drawer open between the robot and its goal: the base goes round it or fails naming it.
The judge and the limits test read the same mug transport of each robot, and the bowl's
test the PR2's bowl transport: the session's runs (``tests/kitchen_transports.py``),
judged as they ran.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import NavigationPathBlocked
from robocram.motion import joint_limits, trajectory_listener
from robocram.plans.basic_actions import park_arms
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose, PoseStamped
from tests.kitchen_transports import SHARED, KitchenTransport, Transports

pytestmark = SHARED  # its transports are other modules' too


@pytest.fixture(params=["pr2", "hsrb", "boxy"])
def mug_transport(
    request: pytest.FixtureRequest, kitchen_transports: Transports
) -> KitchenTransport:
    """The mug taken to the table, judged as it ran: the session's run."""
    return kitchen_transports(request.param, "mug")


def test_every_motion_of_the_transport_is_collision_free(mug_transport: KitchenTransport) -> None:
    world = mug_transport.world
    judged = mug_transport.judge.judged  # the judge found nothing
    kinds = {kind for kind, _ in judged}
    assert {"base", "arm"} <= kinds
    assert sum(n for _, n in judged) > 100
    assert world.bodies.attached_to("mug-1") is None
    low, _ = world.aabb("mug-1")
    assert low[2] == pytest.approx(world.contacts.link_aabb("kitchen", "table_top")[1][2], abs=0.01)


def test_trajectories_respect_limits_and_time_runs_forward(
    mug_transport: KitchenTransport,
) -> None:
    executed = mug_transport.executed
    desc = mug_transport.world.robot(mug_transport.robot).description
    assert executed
    for trajectory in executed:
        times = trajectory.times()
        assert np.all(np.diff(times) > 0.0)
        limits = joint_limits(desc, trajectory.joint_names)
        for i, lim in enumerate(limits):
            positions = trajectory.positions()[:, i]
            velocities = np.array([p.velocities[i] for p in trajectory.points])
            assert np.all(positions >= lim.lower - 1e-6) and np.all(positions <= lim.upper + 1e-6)
            assert np.all(np.abs(velocities) <= lim.velocity * (1 + 1e-6))


def test_going_past_an_open_drawer_goes_round_it_or_names_it(
    make_judge: Callable[..., Any],
) -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    judge = make_judge(world, "pr2")
    world.set_joint_states("kitchen", {"drawer_unit_drawer_3_joint": 0.4})
    drawer = world.contacts.link_aabb("kitchen", "drawer_unit_drawer_3")
    x = (drawer[0][0] + drawer[1][0]) / 2
    world.set_pose("pr2", Pose((x - 1.0, 1.05, 0.0)))  # west of the drawer, before the counter
    goal = PoseStamped("map", (x + 1.0, 1.05, 0.0))  # east of it: straight through is blocked
    try:
        with trajectory_listener(judge), simulated_robot(world, "pr2"):
            park_arms()
            perform(a.motion(type="going", target=a.location(pose=goal)))
    except NavigationPathBlocked as failure:
        assert any("drawer_unit_drawer_3" in name for name in failure.colliding or [])
    else:
        assert world.pose("pr2").position[:2] == pytest.approx((x + 1.0, 1.05), abs=1e-6)
        assert ("base", 0) not in judge.judged and any(k == "base" for k, _ in judge.judged)
    world.close()


def test_the_pr2_takes_the_bowl_out_of_the_drawer_along_free_paths(
    kitchen_transports: Transports,
) -> None:
    run = kitchen_transports("pr2", "bowl")
    world, result = run.world, run.done
    judged = run.judge.judged  # the judge found nothing
    assert result.object_name == "bowl-1" and result.opened  # it came out of a drawer
    assert sum(n for _, n in judged) > 100
    low, _ = world.aabb("bowl-1")
    assert low[2] == pytest.approx(world.contacts.link_aabb("kitchen", "table_top")[1][2], abs=0.01)
    assert world.joint_states("kitchen")["drawer_unit_drawer_3_joint"] == pytest.approx(
        0.0, abs=0.01
    )  # closed again

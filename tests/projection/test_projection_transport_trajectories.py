"""The kitchen transport on the PR2, the HSR and Boxy moves only along collision-free paths.

Each trajectory is judged the moment projection reports it, in the world as it is then
(drawers as the search left them, the mug in the hand), by PyBullet, independently of the
planner: every configuration 1 cm of link travel / 0.02 rad apart along an arm
trajectory, and every pose 1 cm / 0.02 rad apart along a base trajectory, is free, held
objects included. Contacts the motion starts with (a hand on a handle, a mug still on its
counter) and the moving hand's own links (grasping) do not count; every other robot link
and every held object must stay clear.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

from robocram.designators import a
from robocram.motion import BASE_JOINTS, JointTrajectory, joint_limits, trajectory_listener
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.travel_bound import TravelBound
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

TABLE = ("kitchen", "table_top")


class Judge:
    """Checks each reported trajectory against the world at that moment."""

    def __init__(self, world: World, robot: str) -> None:
        self.world = world
        self.robot = robot
        self.judged: list[tuple[str, int]] = []  # (kind, configurations checked)

    def __call__(self, trajectory: JointTrajectory) -> None:
        if trajectory.joint_names == BASE_JOINTS:
            self.judged.append(("base", self._base(trajectory)))
        else:
            self.judged.append((trajectory.kind, self._arm(trajectory)))

    def _hand_links(self, joints: tuple[str, ...]) -> set[str]:
        desc = self.world.robot(self.robot).description
        links: set[str] = set()
        for arm in desc.arms.values():
            if set(arm.joints) & set(joints):
                links |= set(arm.hand_links) | set(arm.gripper_links)
                links |= {arm.end_effector_link, arm.tool_frame}
        return links

    def _arm(self, trajectory: JointTrajectory) -> int:
        world, joints = self.world, trajectory.joint_names
        end = world.joint_states(self.robot)
        points = trajectory.positions()
        start = dict(zip(joints, points[0], strict=True))
        judge = BulletScene(world, self.robot, joints, self._hand_links(joints))
        allowed = set(judge.colliding_at(start))
        bound = TravelBound.of(world, self.robot, joints)
        checked = 0
        for qa, qb in zip(points, points[1:], strict=False):
            n = bound.steps(qa, qb)
            for k in range(1, n + 1):
                q = qa + (qb - qa) * (k / n)
                hits = set(judge.colliding(q)) - allowed
                assert not hits, f"{trajectory.kind} trajectory of {joints} hits {hits} at {q}"
                checked += 1
        world.set_joint_states(self.robot, {j: end[j] for j in joints})
        return checked

    def _base(self, trajectory: JointTrajectory) -> int:
        world, robot = self.world, self.robot
        end = world.pose(robot)
        height = end.position[2]
        points = trajectory.positions()
        judge = BulletScene(world, robot, ())

        def put(x: float, y: float, yaw: float) -> None:
            world.set_pose(robot, Pose((x, y, height), quat.from_euler(0.0, 0.0, yaw)))

        put(*points[0])
        allowed = set(judge.colliding_now())
        checked = 0
        for qa, qb in zip(points, points[1:], strict=False):
            travel = math.dist(qa[:2], qb[:2]) + 0.5 * abs(qb[2] - qa[2])  # 0.5 m: a reach
            n = max(1, math.ceil(travel / 0.01), math.ceil(abs(qb[2] - qa[2]) / 0.02))
            for k in range(1, n + 1):
                put(*(qa + (qb - qa) * (k / n)))
                hits = set(judge.colliding_now()) - allowed
                assert not hits, f"base path hits {hits} at {qa + (qb - qa) * (k / n)}"
                checked += 1
        world.set_pose(robot, end)
        return checked


@pytest.fixture(params=["pr2", "hsrb", "boxy"])
def kitchen(request: pytest.FixtureRequest) -> Iterator[KitchenScene]:
    scene = kitchen_scene(request.param)
    yield scene
    scene.world.close()


def test_every_motion_of_the_transport_is_collision_free(kitchen: KitchenScene) -> None:
    world = kitchen.world
    judge = Judge(world, kitchen.robot)
    with trajectory_listener(judge), simulated_robot(world, kitchen.robot):
        transport("mug", a.location(on=TABLE, for_="mug-1"))
    kinds = {kind for kind, _ in judge.judged}
    assert {"base", "arm"} <= kinds
    assert sum(n for _, n in judge.judged) > 100
    assert world.attached_to("mug-1") is None
    low, _ = world.aabb("mug-1")
    assert low[2] == pytest.approx(world.link_aabb("kitchen", "table_top")[1][2], abs=0.01)


def test_trajectories_respect_limits_and_time_runs_forward(kitchen: KitchenScene) -> None:
    world = kitchen.world
    executed: list[JointTrajectory] = []
    with trajectory_listener(executed.append), simulated_robot(world, kitchen.robot):
        transport("mug", a.location(on=TABLE, for_="mug-1"))
    desc = world.robot(kitchen.robot).description
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

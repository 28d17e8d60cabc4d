"""An independent judge of executed trajectories, for tests: PyBullet, densely, at once.

Each trajectory is judged the moment projection reports it, in the world as it is then.
Every configuration 1 cm of link travel / 0.02 rad apart along an arm, torso, head or
gripper trajectory, and every pose 1 cm / 0.02 rad apart along a base trajectory, must be
free, held objects included; contacts the motion starts with, the moving hand's own links
(grasping) and the fingers on a movable object a gripper closes on do not count. The world
is put back through a snapshot, to the bit: a judged run plans what a plain one does.
"""

from __future__ import annotations

import math

from robocram.motion import BASE_JOINTS, JointTrajectory
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.travel_bound import TravelBound
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World


class Judge:
    """Checks each reported trajectory against the world at that moment."""

    def __init__(self, world: World, robot: str) -> None:
        self.world = world
        self.robot = robot
        self.judged: list[tuple[str, int]] = []  # (kind, configurations checked)

    def __call__(self, trajectory: JointTrajectory) -> None:
        # Put back through a snapshot: a pose read and set again is a last bit off (PyBullet
        # reads a base through a rotation matrix), and a judged run must plan as a plain one.
        with self.world.snapshots.stored_state():
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
        points = trajectory.positions()
        start = dict(zip(joints, points[0], strict=True))
        judge = BulletScene(RobotHandle.of(world, self.robot), joints, self._hand_links(joints))
        allowed = set(judge.colliding_at(start))
        if trajectory.kind == "gripper":  # the fingers may sink into what they squeeze
            allowed |= self._squeezed(judge, trajectory)
        bound = TravelBound.of(RobotHandle.of(world, self.robot), joints)
        checked = 0
        for qa, qb in zip(points, points[1:], strict=False):
            n = bound.steps(qa, qb)
            for k in range(1, n + 1):
                q = qa + (qb - qa) * (k / n)
                hits = set(judge.colliding(q)) - allowed
                assert not hits, f"{trajectory.kind} trajectory of {joints} hits {hits} at {q}"
                checked += 1
        return checked

    def _squeezed(self, judge: BulletScene, trajectory: JointTrajectory) -> set[tuple[str, str]]:
        """The pairs a gripper trajectory ends in: a finger on a movable object (one that
        meets it before the other does sinks in until both squeeze it)."""
        movable = {o.name for o in self.world.objects() if not o.is_static}
        return {
            (link, other)
            for link, other in judge.colliding_at(trajectory.end)
            if other.split("/")[0] in movable
        }

    def _base(self, trajectory: JointTrajectory) -> int:
        world, robot = self.world, self.robot
        height = world.pose(robot).position[2]
        points = trajectory.positions()
        judge = BulletScene(RobotHandle.of(world, robot), ())

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
        return checked

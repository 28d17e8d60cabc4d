"""The world as the checker of whole-body configurations: the base's pose and an arm's joints.

A whole-body step moves the base (``x``, ``y``, ``yaw`` in map, :data:`BASE_JOINTS`) and
an arm at once. Every link of the robot, and what it holds, moves with the base, so the
check is the world's own over all of them (a :class:`BulletScene` of no joints: the base),
with the robot put where the configuration says. The robot is put back, pose and joints,
when a ``posed`` block ends.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Collection, Iterator, Mapping, Sequence

import numpy as np

from robocram.motion.bullet_scene import CLEARANCE_REACH, BulletScene
from robocram.motion.carried_joint import CarriedJoint
from robocram.motion.configuration_checker import Configuration, LinkPair
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.hand_contact import HandContact
from robocram.motion.joint_trajectory import BASE_JOINTS, FloatArray
from robocram.motion.travel_bound import TravelBound, link_radii
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle


def is_whole_body(names: Sequence[str]) -> bool:
    """Whether a trajectory of ``names`` moves the base (``x``, ``y``, ``yaw``) and joints."""
    return len(names) > len(BASE_JOINTS) and tuple(names[: len(BASE_JOINTS)]) == BASE_JOINTS


def put_configuration(robot: RobotHandle, names: Sequence[str], positions: Sequence[float]) -> None:
    """Put ``robot`` at ``positions`` of ``names``: joints, or a whole-body configuration."""
    values = dict(zip(names, (float(p) for p in positions), strict=True))
    if is_whole_body(names):
        put_base_and_joints(robot, values)
    else:
        robot.world.set_joint_states(robot.name, values)


def put_base_and_joints(robot: RobotHandle, values: Mapping[str, float]) -> None:
    """Put ``robot`` where ``values`` say: the base joints ``x``, ``y``, ``yaw`` (map) as
    its pose at its height, the others as joint values."""
    world = robot.world
    height = world.pose(robot.name).position[2]
    turn = quat.from_euler(0.0, 0.0, values["yaw"])
    world.set_pose(robot.name, Pose((values["x"], values["y"], height), turn))
    world.set_joint_states(robot.name, {k: v for k, v in values.items() if k not in BASE_JOINTS})


class WholeBodyScene:
    """Checks configurations ``(x, y, yaw, *arm joints)`` of ``robot`` in its world."""

    def __init__(
        self,
        robot: RobotHandle,
        arm_joints: Sequence[str],
        allowed_pairs: Collection[LinkPair] = (),
        contacts: Collection[ContactAllowance] = (),
        allowed_links: Collection[str] = (),
        hand: HandContact | None = None,
        carried: Sequence[CarriedJoint] = (),
    ) -> None:
        self.handle = robot
        self.arm_joints = tuple(arm_joints)
        self.carried = tuple(c for c in carried if c.line is not None)  # moved with the tool
        self._joints = (*BASE_JOINTS, *self.arm_joints)
        self.scene = BulletScene(
            robot, (), allowed_links, allowed_pairs=allowed_pairs, hand=hand, contacts=contacts
        )
        self._posed = False

    @property
    def joints(self) -> tuple[str, ...]:
        """The base's ``x``, ``y``, ``yaw`` (map), then the arm's joints."""
        return self._joints

    @property
    def reach(self) -> float:
        """How far [m] clearance queries look."""
        return CLEARANCE_REACH

    def now(self) -> FloatArray:
        """The configuration the robot is in."""
        world, name = self.handle.world, self.handle.name
        pose = world.pose(name)
        yaw = quat.to_euler(pose.orientation)[2]
        joints = world.joint_states(name)
        return np.array(
            [pose.position[0], pose.position[1], yaw, *(joints[j] for j in self.arm_joints)]
        )

    @contextlib.contextmanager
    def posed(self) -> Iterator[None]:
        """Checks inside the block leave the robot where they put it; it is put back, its
        pose and its joints, when the block ends."""
        if self._posed:
            yield
            return
        world, name = self.handle.world, self.handle.name
        pose = world.pose(name)
        self._posed = True
        try:
            with self.scene.posed():
                yield
        finally:
            self._posed = False
            world.set_pose(name, pose)

    def _put(self, q: Configuration) -> None:
        put_base_and_joints(
            self.handle, dict(zip(self._joints, (float(v) for v in q), strict=True))
        )

    def colliding(self, q: Configuration, first_only: bool = False) -> list[LinkPair]:
        """The colliding ``(robot link | held object, other)`` pairs at ``q``."""
        with self.posed():
            self._put(q)
            return self.scene.colliding_now(first_only)

    def is_free(self, q: Configuration) -> bool:
        """Whether ``q`` collides with nothing."""
        return not self.colliding(q, first_only=True)

    def clearance(self, q: Configuration, reach: float = CLEARANCE_REACH) -> float:
        """How far [m] the robot (and what it holds) is from anything it may not touch."""
        return min(self.clearances(q, reach).values(), default=reach)

    def clearances(self, q: Configuration, reach: float = CLEARANCE_REACH) -> dict[str, float]:
        """Per link (or held object) nearer than ``reach`` [m] to what it may not touch."""
        with self.posed():
            self._put(q)
            return self.scene.clearances_now(reach)

    def bound(self, qa: FloatArray, qb: FloatArray, arm: TravelBound) -> TravelBound:
        """How far any point moves from ``qa`` to ``qb`` per unit of each joint: 1 for
        ``x`` and ``y``; for ``yaw`` the farthest any point gets from the base's axis on
        the way (its distance at ``qa`` plus how far the arm's joints can carry it); the
        arm's own levers (``arm``, for :attr:`arm_joints`) for the rest."""
        with self.posed():
            self._put(qa)
            far = self._farthest()
        carried = arm.travel(qa[3:], qb[3:])
        lever = np.concatenate(([1.0, 1.0, far + carried], arm.lever))
        return TravelBound(self._joints, lever, arm.max_link_travel, arm.max_joint_step)

    def _farthest(self) -> float:
        """The farthest [m] any point of the robot or what it holds is from the base's
        vertical axis, as it stands."""
        world, name = self.handle.world, self.handle.name
        radii = link_radii(self.handle)
        origin = world.pose(name).position
        links = list(radii)
        frames = world.bodies.link_frames(name, links)
        return max(
            (math.hypot(f[0] - origin[0], f[1] - origin[1]) + radii[link]
             for link, f in zip(links, frames, strict=True)),
            default=0.0,
        )  # fmt: skip

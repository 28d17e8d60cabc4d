"""The plan side's motions for a robot behind ROS: checked in a world if given, always timed.

Every joint motion sent over ROS is a timed trajectory (``robocram.motion``): positions,
velocities, accelerations and times from the start, within the joints' limits. With a
projection ``World`` of the robot's environment, the world is first put into the robot's
state as ROS reports it (joint states and base pose), then the motion is planned in it as
projection plans it: the straight joint segment if it is free, else around obstacles
(OMPL), a Cartesian line for ``allow_hand`` tool motions, and the base's path checked
before a ``move_base`` goal is sent. Without a world no environment is checked: the
trajectory is the straight joint segment, timed.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field, replace

from robocram.motion import (
    BasePath,
    JointTrajectory,
    MotionSettings,
    joint_limits,
    plan_arm_motion,
    plan_base_path,
    plan_tool_line,
    time_parameterize,
)
from robocram.motion.collision_modes import (
    COLLISION_MODES,
    IKCollisionCheck,
    allowed_links,
    hand_bound,
    ik_collision_check,
)
from robocram.motion.joint_goal import finite_goal, motion_goal
from robocram.robots import LoadedDescription
from robocram.ros.errors import RosCommandError, RosConfigError
from robocram.tf import Pose
from robocram.world import RobotHandle, World


@dataclass(frozen=True)
class ClampedGoal:
    """A joint goal moved into the limits; ``culprits`` are ``joint: (asked, lower, upper)``
    for goals beyond the hard limits, ``softened`` those only beyond the soft ones."""

    goal: dict[str, float]  # [rad | m] within the working (soft, else hard) limits
    culprits: dict[str, tuple[float, float, float]]
    softened: dict[str, tuple[float, float]] = field(default_factory=dict)  # asked, sent

    def describe(self, robot_name: str) -> str:
        """What was clamped, in words."""
        return (
            "joint goals outside the limits, clamped: "
            + ", ".join(
                f"{j}={asked} not in [{low}, {high}]"
                for j, (asked, low, high) in self.culprits.items()
            )
            + f" ({robot_name})"
        )


def _bounds(limits: tuple[float | None, float | None]) -> tuple[float, float]:
    low, high = limits
    return (-math.inf if low is None else low, math.inf if high is None else high)


def clamp_goal(desc: LoadedDescription, goal: Mapping[str, float]) -> ClampedGoal:
    """``goal`` with every value inside its joint's working limits.

    A real robot's controllers stop a joint at its ``<safety_controller>`` soft limits
    (the PR2's), so the goal sent stays inside them. A value beyond the hard limits is
    a culprit (the motion then fails, as in projection); a value between a soft and the
    hard limit is moved to the soft limit and is no failure: the robot ends there.
    """
    clamped: dict[str, float] = {}
    culprits: dict[str, tuple[float, float, float]] = {}
    softened: dict[str, tuple[float, float]] = {}
    for joint, value in goal.items():
        spec = desc.model.joints.get(joint)
        if spec is None or not spec.movable:
            raise RosCommandError(f"{joint!r} is not a movable joint of {desc.name}")
        asked = finite_goal(joint, value)
        low, high = _bounds((spec.lower, spec.upper))
        soft_low, soft_high = _bounds(spec.working_limits)
        clamped[joint] = min(max(asked, soft_low), soft_high)
        if not low <= asked <= high:
            culprits[joint] = (asked, low, high)
        elif clamped[joint] != asked:
            softened[joint] = (asked, clamped[joint])
    return ClampedGoal(clamped, culprits, softened)


class MotionPlanner:
    """Plans the trajectories the ROS process modules send (one per robot connection)."""

    def __init__(
        self,
        desc: LoadedDescription,
        world: World | None = None,
        settings: MotionSettings | None = None,
    ) -> None:
        self.desc = desc
        self.world = world
        self.settings = settings or MotionSettings()
        if world is not None:
            names = [r.name for r in world.robots()]
            if desc.name not in names:
                raise RosConfigError(
                    f"the world given for {desc.name} has robots {names}, not {desc.name!r}; "
                    f"pass a world with the robot in it (e.g. tabletop_scene({desc.name!r}).world)"
                )
        self.robot = None if world is None else RobotHandle.of(world, desc.name)

    def joint_motion(
        self,
        goal: Mapping[str, float],
        current: Mapping[str, float],
        *,
        arm: str | None = None,
        mode: str = "avoid_all",
        what: str = "the joints",
        kind: str = "arm",
        plan: bool = True,
        touching: str | None = None,
    ) -> JointTrajectory:
        """The timed motion of the joints in ``goal`` (within limits) from where they are.

        With a world it is checked (and planned round obstacles unless ``plan`` is False:
        a lift has one way) in the collision mode of the motion; under ``allow_hand``
        ``arm``'s hand may touch ``touching`` (``"none"``: any object) no deeper than the
        bound projection keeps (``HandContact``); None: its links touch anything,
        unbounded. The world must show the robot's state now (``world_mirror.py``).
        Without a world, ``current`` is the start of a straight move. ``kind`` names the
        motion in the trajectory (``arm``, ``torso``, ``head``).

        Raises:
            ManipulationPathBlocked: the world blocks every way there (nothing was sent).
        """
        joints = tuple(j for j in goal if self.desc.model.joints[j].mimic is None)
        if self.robot is None:
            limits = joint_limits(self.desc, joints)
            # a real robot may report a joint a hair beyond its limit; a trajectory cannot
            start = [
                min(max(current[j], lim.lower), lim.upper)
                for j, lim in zip(joints, limits, strict=True)
            ]
            end = motion_goal(self.desc, joints, start, goal)
            return time_parameterize(self.desc.name, joints, [start, end], limits, kind=kind)
        mode = _mode(mode)
        settings = replace(self.settings, check=False) if mode == "allow_all" else self.settings
        settings = settings if plan else replace(settings, plan=False)
        spec = self.desc.arms[arm] if arm is not None else None
        hand = hand_bound(spec, mode, touching) if spec and touching is not None else None
        unbounded = allowed_links(spec, mode) if spec and touching is None else set()
        motion = plan_arm_motion(
            self.robot,
            {j: float(goal[j]) for j in joints},
            allowed_links=unbounded,
            settings=settings,
            what=what,
            kind=kind,
            hand=hand,
        )
        return motion.trajectory

    def tool_line(
        self, arm: str, target_in_base: Pose, mode: str, touching: str | None = None
    ) -> JointTrajectory | None:
        """The arm's straight tool line to ``target_in_base`` if the world lets it all be
        followed (``allow_hand`` motions: approach, lift, retreat), else None; the hand
        may touch ``touching`` as in :meth:`joint_motion`."""
        if self.robot is None or _mode(mode) != "allow_hand":
            return None
        spec = self.desc.arms[arm]
        hand = hand_bound(spec, "allow_hand", touching) if touching is not None else None
        unbounded = allowed_links(spec, "allow_hand") if touching is None else set()
        line = plan_tool_line(
            self.robot,
            arm,
            target_in_base,
            allowed_links=unbounded,
            settings=self.settings,
            hand=hand,
        )
        return line.trajectory if line.fraction >= 1.0 else None

    def base_path(self, goal_in_map: Pose, allowed_links: Collection[str] = ()) -> BasePath | None:
        """The base's checked path to ``goal_in_map`` in the world (None without a world);
        ``allowed_links`` may touch things on the way (a hand at what it grasps).

        Raises:
            NavigationPoseUnreachable: the robot would collide at the goal.
            NavigationPathBlocked: no path leads there in the world.
        """
        if self.robot is None:
            return None
        return plan_base_path(
            self.robot, goal_in_map, seed=self.settings.seed, allowed_links=allowed_links
        )

    def ik_check(self, arm: str, joints: tuple[str, ...], mode: str) -> IKCollisionCheck | None:
        """IK's collision check for ``arm`` moving ``joints`` in ``mode`` (None without a
        world, or for ``allow_all``); the world must show the robot's state now."""
        if self.robot is None:
            return None
        return ik_collision_check(self.robot, self.desc.arms[arm], joints, mode)


def _mode(mode: str) -> str:
    mode = mode.replace("-", "_")
    if mode not in COLLISION_MODES:
        raise RosCommandError(f"unknown collision mode {mode!r}; use one of {COLLISION_MODES}")
    return mode

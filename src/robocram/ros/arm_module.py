"""The arms of a robot behind ROS: IK and paths on the plan side, timed trajectory goals.

``move_tcp`` reads the joint states and the base pose from ROS, solves IK (pinocchio,
seeded with the current joints, first with the torso held, then free) and sends the torso
and then the arm as whole timed ``FollowJointTrajectory`` goals; the reached tool frame is
then read from tf and checked against the target (1 cm / 0.05 rad, as in projection).
With a world given to ``ros_robot`` the collision mode counts as in projection: IK rejects
colliding solutions, ``allow_hand`` motions follow a straight tool line when they can, and
joint paths go round what is in the world (``motion_planner.py``). Without one, nothing
in the environment is checked: the path is the straight joint segment.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robocram.designators import SIDES
from robocram.execution.failures import (
    ManipulationGoalNotReached,
    ManipulationPathBlocked,
    NavigationPathBlocked,
    NavigationPoseUnreachable,
)
from robocram.kinematics import (
    BaseMotion,
    IKOptions,
    IKResult,
    PlanarBase,
    base_in_ik,
    solve_ik,
)
from robocram.motion.collision_modes import COLLISION_MODES, hand_links
from robocram.motion.reach_failure import unreachable
from robocram.motion.tool_goal import IK_RANDOM_SEED, ensure_reached, joint_values
from robocram.robots import RobotDescription
from robocram.ros.errors import RosCommandError
from robocram.ros.goal_runner import FailureFactory
from robocram.ros.part_motion import move_part
from robocram.ros.process_modules import RosProcessModule, send_base_goal
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat

TORSO_MOVE = 1e-4  # [m | rad] IK torso changes smaller than this are not sent
BASE_TRAVEL = PlanarBase()  # how far IK may move the base, as in projection


class ArmPM(RosProcessModule):
    """The arms: ``move_tcp`` and ``move_joints``, one arm or both."""

    name = "ros_arms"
    resource = "arms"

    def move_tcp_both(self, left: Any, right: Any, mode: str) -> tuple[Pose, ...]:
        """Move the tool frames of the arms on the left and the right side."""
        return tuple(
            self.move_tcp(side, pose, mode) for side, pose in zip(SIDES, (left, right), strict=True)
        )

    def move_joints_both(
        self, left: object, right: object, mode: str = "avoid_all"
    ) -> tuple[dict[str, float], ...]:
        """Move the joints of the arms on the left and the right side."""
        sides = zip(SIDES, (left, right), strict=True)
        return tuple(self.move_joints(s, c, mode) for s, c in sides)

    def move_part(self, arm: str, part: str, joint: str, handle: str, goal: float) -> float:
        """Open or close a drawer or door: hold ``handle`` and move ``joint`` of ``part``
        to ``goal`` [m | rad] (``part_motion.py``); return the joint value reached."""
        side = self.client.desc.arm_called(arm)
        return move_part(self.client, self, side, part, joint, handle, float(goal))

    def _solve(
        self, arm: str, target_in_base: Pose, mode: str, travel: PlanarBase = BASE_TRAVEL
    ) -> IKResult:
        desc = self.client.desc
        seed = self.client.actuated_joint_states()
        planner = self.client.planner()  # its world (if any) in the robot's state now
        result = IKResult(False)
        for use_torso, base in _attempts(desc, arm, travel):
            moving = desc.arms[arm].joints + ((desc.torso_joint,) if use_torso else ())
            check = planner.ik_check(arm, tuple(j for j in moving if j is not None), mode)
            result = solve_ik(
                desc,
                arm,
                target_in_base,
                seed=seed,
                options=IKOptions(use_torso=use_torso, base=base, random_seed=IK_RANDOM_SEED),
                collision_check=check,
            )
            if result.success:
                break
        return result

    def _move_base(
        self, arm: str, motion: BaseMotion, mode: str, arm_first: Callable[[], None]
    ) -> bool:
        """Drive the base by IK's ``motion`` (its own frame) with the arm as it is; if the
        arm as it is does not fit there, ``arm_first`` and then the base (True: the arm is
        there already). The hand's links may touch things under ``allow_hand``.

        Raises:
            NavigationPathBlocked, NavigationPoseUnreachable: neither order works (the
                first order's failure); no base goal was sent.
        """
        client = self.client
        start = client.base_pose()
        moved = start * motion.pose()
        yaw = quat.to_euler(moved.orientation)[2]
        base_goal = Pose((moved.position[0], moved.position[1], start.position[2]),
                         quat.from_euler(0.0, 0.0, yaw))  # fmt: skip
        free = hand_links(client.arm(arm)) if mode.replace("-", "_") == "allow_hand" else set()
        arm_moved = False
        try:
            client.planner().base_path(base_goal, free)
        except (NavigationPathBlocked, NavigationPoseUnreachable) as failure:
            arm_first()
            arm_moved = True
            try:
                client.planner().base_path(base_goal, free)
            except (NavigationPathBlocked, NavigationPoseUnreachable):
                raise failure from None
        send_base_goal(client, base_goal)
        return arm_moved

    def _torso(self, arm: str, solution: dict[str, float], target: object, mode: str) -> None:
        """Send the torso to IK's value in ``solution``, if it moves."""
        torso = self.client.desc.torso_joint
        if torso in solution and (
            abs(solution[torso] - self.client.joint_states()[torso]) > TORSO_MOVE
        ):
            self._move("torso", {torso: solution[torso]}, arm, target, mode)

    def move_tcp(
        self,
        arm: str,
        target: PoseStamped | Any,
        collision_mode: str = "avoid_all",
        touching: str | None = "none",
        base_travel: PlanarBase = BASE_TRAVEL,
    ) -> Pose:
        """Put ``arm``'s tool frame at ``target``; return the reached pose in the fixed frame.
        ``base_travel`` bounds how far IK may move the base of an arm that reaches with it.

        Under ``allow_hand`` the hand may touch ``touching`` (an object or ``object/link``;
        ``"none"``: any object) no deeper than projection's bound, in the arm's motion and
        tool line (None: anything, unbounded, as articulations over ROS still ask); IK's
        check lets the hand's links touch, so a goal that puts the hand deeper fails in
        planning (``ManipulationPathBlocked``), with nothing sent.

        Raises:
            ManipulationPoseUnreachable: IK found no (collision-free, with a world) solution.
            ManipulationPathBlocked: the world blocks every path there; nothing was sent.
            ManipulationGoalNotReached: the controller failed, or the tool ended too far off.
        """
        client = self.client
        arm = client.desc.arm_called(arm)
        spec = client.arm(arm)
        target_in_map = client.in_map(target)
        to_base = client.base_pose().inverse()
        result = self._solve(arm, to_base * target_in_map, collision_mode, base_travel)
        if not result.success:
            mode = collision_mode if client.has_world else "allow_all"
            raise unreachable(client.desc, arm, target, target_in_map, mode, result)
        solution = dict(result.joint_positions)
        goal = {j: solution[j] for j in spec.joints}
        motion = result.base_motion
        if motion is not None and motion != BaseMotion():

            def arm_first() -> None:
                self._torso(arm, solution, target, collision_mode)
                self._move(f"arm({arm})", goal, arm, target, collision_mode, touching)

            if self._move_base(arm, motion, collision_mode, arm_first):
                reached = client.frame_pose(spec.tool_frame)
                return ensure_reached(client.name, arm, reached, target, target_in_map)
        self._torso(arm, solution, target, collision_mode)
        target_in_base = client.base_pose().inverse() * target_in_map
        line = client.planner().tool_line(arm, target_in_base, collision_mode, touching)
        if line is not None:
            client.follow_trajectory(f"arm({arm})", line, self._failure(arm, target))
        else:
            self._move(f"arm({arm})", goal, arm, target, collision_mode, touching)
        reached = client.frame_pose(spec.tool_frame)
        return ensure_reached(client.name, arm, reached, target, target_in_map)

    def move_joints(
        self,
        arm: str,
        configuration: object,
        collision_mode: str = "avoid_all",
        touching: str | None = "none",
    ) -> dict[str, float]:
        """Move ``arm``'s joints to a ``{joint: value}`` or ``[[joint, value], ...]`` config.

        The keys are projection's: with a world given to ``ros_robot`` the path is checked
        in ``collision_mode`` and an ``allow_hand`` hand may touch ``touching`` (``"none"``:
        any object) no deeper than projection's bound. Without a world ROS cannot bound
        the hand (nor check anything): the path is the straight joint segment whatever
        the mode.

        Raises:
            RosCommandError: ``collision_mode`` is none of CRAM's modes, or a joint is not
                the arm's; nothing was sent.
        """
        if collision_mode.replace("-", "_") not in COLLISION_MODES:
            raise RosCommandError(
                f"unknown collision mode {collision_mode!r} for moving {self.client.name}'s "
                f"{arm} arm's joints; use one of {COLLISION_MODES}"
            )
        arm = self.client.desc.arm_called(arm)
        values = joint_values(configuration)
        allowed = set(self.client.arm(arm).joints)
        unknown = sorted(set(values) - allowed)
        if unknown:
            raise RosCommandError(
                f"joints {unknown} are not in {self.client.name}'s {arm} arm {sorted(allowed)}"
            )
        self._move(f"arm({arm})", values, arm, values, collision_mode, touching)
        joints = self.client.joint_states()
        return {j: joints[j] for j in values}

    def _move(
        self,
        resource: str,
        goal: dict[str, float],
        arm: str,
        target: object,
        mode: str,
        touching: str | None = None,
    ) -> None:
        """Plan the timed motion (in the world, if any) and send it; a blocked path raises
        ``ManipulationPathBlocked`` naming the arm and target before anything is sent."""
        failure = self._failure(arm, target)
        try:
            self.client.move_joints(resource, goal, failure, arm=arm, mode=mode, touching=touching)
        except ManipulationPathBlocked as failure:
            failure.arm = arm
            failure.target = target
            raise

    @staticmethod
    def _failure(arm: str, target: object) -> FailureFactory:
        return lambda text: ManipulationGoalNotReached(text, arm=arm, target=target)


def _attempts(
    desc: RobotDescription, arm: str, travel: PlanarBase
) -> list[tuple[bool, PlanarBase | None]]:
    """(use_torso, base) of each IK query, in order, as projection asks them: the arm, then
    the torso; or, for an arm that reaches with its base (``base_in_ik``), one query with
    the torso and the base within ``travel``."""
    torso = desc.torso_joint is not None
    if base_in_ik(desc, arm):
        return [(torso, travel)]
    return [(False, None), (True, None)] if torso else [(False, None)]

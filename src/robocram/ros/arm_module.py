"""The arms of a robot behind ROS: IK on the plan side, ``FollowJointTrajectory`` goals.

``move_tcp`` reads the joint states and the base pose from ROS, solves IK (pinocchio,
seeded with the current joints, first with the torso held, then free) and sends the torso
and arm trajectories; the reached tool frame is then read from tf and checked against the
target (1 cm / 0.05 rad, as in projection). Collision avoidance is the robot's motion
planner's job on a real robot (CRAM hands this to giskard or MoveIt), so the collision
mode is passed on but not checked here.
"""

from __future__ import annotations

from typing import Any

from robocram.designators import SIDES
from robocram.execution.failures import ManipulationGoalNotReached
from robocram.kinematics import IKResult, solve_ik
from robocram.projection.arm import IK_RANDOM_SEED, ensure_reached, joint_values
from robocram.projection.reach_failure import unreachable
from robocram.ros.errors import RosCommandError
from robocram.ros.process_modules import RosProcessModule
from robocram.tf import Pose, PoseStamped

TORSO_MOVE = 1e-4  # [m | rad] IK torso changes smaller than this are not sent


class ArmPM(RosProcessModule):
    """The arms: ``move_tcp`` and ``move_joints``, one arm or both."""

    name = "ros_arms"
    resource = "arms"

    def move_tcp_both(self, left: Any, right: Any, mode: str) -> tuple[Pose, ...]:
        """Move the tool frames of the arms on the left and the right side."""
        return tuple(
            self.move_tcp(side, pose, mode) for side, pose in zip(SIDES, (left, right), strict=True)
        )

    def move_joints_both(self, left: object, right: object) -> tuple[dict[str, float], ...]:
        """Move the joints of the arms on the left and the right side."""
        return tuple(self.move_joints(s, c) for s, c in zip(SIDES, (left, right), strict=True))

    def move_part(self, arm: str, part: str, joint: str, handle: str, goal: float) -> float:
        """Not over ROS yet: articulated parts need a whole-body controller (CRAM: giskard)."""
        raise RosCommandError(
            f"robocram.ros has no ROS interface for moving-articulation ({part}.{joint} with "
            f"{arm}'s hand); run it in projection, or add a controller interface for it"
        )

    def _solve(self, arm: str, target_in_base: Pose) -> IKResult:
        desc = self.client.desc
        seed = self.client.actuated_joint_states()
        result = IKResult(False)
        for use_torso in [False, True] if desc.torso_joint is not None else [False]:
            result = solve_ik(
                desc,
                arm,
                target_in_base,
                seed=seed,
                use_torso=use_torso,
                random_seed=IK_RANDOM_SEED,
            )
            if result.success:
                break
        return result

    def move_tcp(
        self, arm: str, target: PoseStamped | Any, collision_mode: str = "avoid_all"
    ) -> Pose:
        """Put ``arm``'s tool frame at ``target``; return the reached pose in the fixed frame."""
        client = self.client
        arm = client.desc.arm_called(arm)
        spec = client.arm(arm)
        target_in_map = client.in_map(target)
        result = self._solve(arm, client.base_pose().inverse() * target_in_map)
        if not result.success:
            raise unreachable(client.desc, arm, target, target_in_map, "allow_all", result)
        solution = dict(result.joint_positions)
        torso = client.desc.torso_joint
        if torso in solution:
            value = solution.pop(torso)
            if abs(value - client.joint_states()[torso]) > TORSO_MOVE:
                self._send("torso", {torso: value}, arm, target)
        self._send(f"arm({arm})", {j: solution[j] for j in spec.joints}, arm, target)
        reached = client.frame_pose(spec.tool_frame)
        return ensure_reached(client.name, arm, reached, target, target_in_map)

    def move_joints(self, arm: str, configuration: object) -> dict[str, float]:
        """Move ``arm``'s joints to a ``{joint: value}`` or ``[[joint, value], ...]`` config."""
        arm = self.client.desc.arm_called(arm)
        values = joint_values(configuration)
        allowed = set(self.client.arm(arm).joints)
        unknown = sorted(set(values) - allowed)
        if unknown:
            raise RosCommandError(
                f"joints {unknown} are not in {self.client.name}'s {arm} arm {sorted(allowed)}"
            )
        self._send(f"arm({arm})", values, arm, values)
        joints = self.client.joint_states()
        return {j: joints[j] for j in values}

    def _send(self, resource: str, goal: dict[str, float], arm: str, target: Any) -> None:
        self.client.follow_joints(
            resource,
            goal,
            lambda text: ManipulationGoalNotReached(text, arm=arm, target=target),
        )

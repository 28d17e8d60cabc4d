"""Joint motions of the torso, the head and the grippers: checked and timed, then followed.

They are planned as arm motions are (``motion.plan_arm_motion``: the straight segment in
joint space, checked densely against the world with what the robot holds, timed under
the joints' limits), and followed with :func:`~robocram.projection.trajectory_follower.follow`,
so listeners and traces see them with their ``kind`` (``torso``, ``head``, ``gripper``).
A lift or a gripper has one way to its goal, so these motions are not planned round
obstacles: a blocked one fails before anything moves, and each caller turns that into its
resource's typed failure. Contacts the motion starts with are allowed, as for the arms.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import replace

from robocram.motion import plan_arm_motion
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.hand_contact import HandContact
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow


def move_along_checked(
    robot: ProjectedRobot,
    goal: Mapping[str, float],
    *,
    kind: str,
    what: str,
    allowed_pairs: Collection[LinkPair] = (),
    plan: bool = False,
    hand: HandContact | None = None,
) -> dict[str, float]:
    """Move the joints of ``goal`` [rad | m] (within their limits) along a checked, timed
    trajectory; return their values reached. ``plan``: search a way round what blocks
    the straight one (a pan-tilt head can tilt up to pan past a shelf); ``hand``: what
    the fingers may squeeze, within its bound (the trajectory stores it).

    Raises:
        ManipulationPathBlocked: the way there collides (nothing moved); it names the
            colliding pairs and where along the way they are.
    """
    settings = robot.motion if plan else replace(robot.motion, plan=False)
    checked = planned_against(robot)
    motion = plan_arm_motion(
        robot.handle, goal, settings=settings, what=what, kind=kind,
        allowed_pairs=allowed_pairs, hand=hand,
    )  # fmt: skip
    follow(robot, motion.trajectory, checked)
    now = robot.world.joint_states(robot.name)
    return {joint: now[joint] for joint in goal}

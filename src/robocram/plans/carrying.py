"""Carrying: hold what the robot has in a carrying pose while it drives, CRAM's ``carrying``.

The carrying pose of an arm is its parking configuration, which the robot's description
gives for driving (arms in, over the base); the held object comes along, and the motion
is checked with it, so an object too big to tuck in fails as ``ManipulationPathBlocked``
instead of sweeping through the base. With a ``target`` the robot then drives there
carrying it.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.plans.basic_actions import navigate, park_arms
from robocram.plans.errors import PlanSetupError
from robocram.plans.known_robot import KnownRobot, current_robot
from robocram.plans.stands import map_pose
from robocram.tf import Pose


@dataclass(frozen=True)
class Carried:
    """What carrying did: the object each arm holds, and where the base ended (map)."""

    held: dict[str, str]  # arm -> object name
    base: Pose


def held_objects(robot: KnownRobot) -> dict[str, str]:
    """The object each arm of ``robot`` holds now (arms holding nothing left out)."""
    return robot.held_objects(robot.grasping_arms())


def carry(target: object = None, arm: str | None = None) -> Carried:
    """Put each arm that holds something (or ``arm``) into its carrying pose, then drive to
    ``target`` if one is given (a pose or a location designator).

    Raises:
        PlanSetupError: the robot holds nothing (in ``arm``).
        ManipulationPathBlocked: an arm cannot tuck in what it holds.
        NavigationPoseUnreachable: no way to ``target``.
    """
    robot = current_robot()
    held = held_objects(robot)
    if arm is not None:
        held = {arm: held[arm]} if arm in held else {}
    if not held:
        raise PlanSetupError(
            f"{robot.name} holds nothing{f' in its {arm} arm' if arm else ''} to carry; pick "
            "something up first (picking-up, fetching)"
        )
    for holding in held:
        park_arms(holding)
    if target is not None:
        navigate(target)
    return Carried(held, map_pose(robot.base_frame()))

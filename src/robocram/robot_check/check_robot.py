"""Check a robot description by driving it: the report card of ``robocram robot check``.

The names and values are checked against the URDF first; then the robot is loaded alone
in a world and each part moves once. Every check runs even when an earlier one failed
(where it can), so one run names every fault.
"""

from __future__ import annotations

from collections.abc import Callable

from robocram.projection.projected_robot import ProjectedRobot
from robocram.robot_check import arm_checks, head_checks
from robocram.robot_check.loading_check import load_for_check
from robocram.robot_check.part_presence import part_presence
from robocram.robot_check.report_card import CheckResult, ReportCard
from robocram.robot_check.stand_in_blame import blame_stand_ins
from robocram.robots import ArmDescription, RobotDescription
from robocram.world import World


def check_robot(desc: RobotDescription) -> ReportCard:
    """Run every check on ``desc``; the card says what passed and how to fix what failed."""
    results: list[CheckResult] = []
    loaded = load_for_check(desc, results)
    if loaded is None:
        return ReportCard(desc.name, tuple(results))
    world = World()
    try:
        world.bodies.add_floor()
        robot = ProjectedRobot.of(world, world.add_robot(loaded).name)
        results += _drive(robot)
    finally:
        world.close()
    hands = {k: (*a.hand_links, *a.gripper_links) for k, a in loaded.arms.items()}
    return ReportCard(desc.name, tuple(blame_stand_ins(loaded.model, results, hands)))


def _guarded(name: str, check: Callable[[], CheckResult | list[CheckResult]]) -> list[CheckResult]:
    """The check's results; an error it did not expect fails it, naming the error."""
    try:
        found = check()
    except Exception as err:  # noqa: BLE001 - a checker reports what breaks, it does not crash
        detail = f"stopped by {type(err).__name__}: {err}"
        return [CheckResult(name, False, detail, "report this with the description")]
    return found if isinstance(found, list) else [found]


def _drive(robot: ProjectedRobot) -> list[CheckResult]:
    desc = robot.description
    results: list[CheckResult] = part_presence(desc)
    _park(robot)
    if desc.cameras:
        results += _guarded("camera", lambda: head_checks.camera_forward(robot))
    results += _guarded("torso", lambda: head_checks.torso(robot))
    for key, arm in desc.arms.items():
        if key != desc.neck_arm:
            results += _arm(robot, key, arm)
    if desc.cameras:
        results += _guarded("look", lambda: head_checks.look_and_detect(robot))
    return results


def _park(robot: ProjectedRobot) -> None:
    """Start as a scene does: every arm and the neck parked (set, not driven: a robot is
    never at its URDF's zeros, which may fold an arm into itself); the parking check then
    judges the parked pose and drives to it again after the reach."""
    desc = robot.description
    values = {j: v for arm in desc.arms.values() for j, v in arm.parking.items()}
    values.update(desc.neck_parking)
    robot.world.set_joint_states(robot.name, values)


def _arm(robot: ProjectedRobot, key: str, arm: ArmDescription) -> list[CheckResult]:
    results = _guarded(f"{key} arm: parking", lambda: arm_checks.parking(robot, key, arm))
    results += _guarded(f"{key} arm: tool frame", lambda: arm_checks.tool_frame(robot, key, arm))
    if arm.gripper_joints:
        results += _guarded(f"{key} arm: gripper", lambda: arm_checks.gripper(robot, key, arm))
    results += _guarded(f"{key} arm: reach", lambda: arm_checks.reach_and_grip(robot, key, arm))
    _guarded(f"{key} arm: parking", lambda: arm_checks.parking(robot, key, arm))
    return results

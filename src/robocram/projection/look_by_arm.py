"""Looking with a camera the arm carries (a wrist camera, no neck): a viewing pose by IK.

The camera frame is put, by IK on the arm's chain with the camera as its tip, at a place
from which its optical axis (z) meets the target with the image upright. The places are
tried in order: where the camera is now (the arm only turns it), then on a ring over the
target on the side of the arm's base, at a few distances and elevations (a step back
and up, so the hand does not hide what it looks at). Each IK solution is collision-checked
as an arm motion avoiding everything, and the arm moves there along a checked, timed
trajectory (planned round obstacles). IK is counted and seeded: the same look gives the
same joints on any machine.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.execution import checkpoint
from robocram.execution.failures import ManipulationPathBlocked, PtuGoalUnreachable
from robocram.kinematics import IKOptions, IKResult, solve_ik
from robocram.motion.tool_goal import IK_RANDOM_SEED
from robocram.projection.collision_mode import collision_check, putting_back_once
from robocram.projection.joint_motion import move_along_checked
from robocram.projection.look_failures import look_blocked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose, Vector3
from robocram.tf.optical_look_at import optical_look_at

VIEW_DISTANCES = (0.45, 0.35, 0.6)  # [m] from the camera to the target on the ring
VIEW_ELEVATIONS = (math.radians(55.0), math.radians(35.0), math.radians(75.0))
VIEW_RESTARTS = 20  # IK descents after the first per viewing place
MIN_DISTANCE = 0.05  # [m] a camera this close to its target cannot look at it


def _ring(robot: ProjectedRobot, arm: str, target: np.ndarray) -> list[np.ndarray]:
    """Viewing places over ``target`` on the side of ``arm``'s base, nearest first."""
    base_link = robot.arm(arm).base_link or robot.description.base_frame
    shoulder = np.asarray(robot.world.link_pose(robot.name, base_link).position, float)
    toward = shoulder - target
    toward[2] = 0.0
    if np.linalg.norm(toward) < 1e-6:
        toward = np.asarray(robot.base_pose().matrix()[:3, 0], float) * -1.0
        toward[2] = 0.0
    toward /= np.linalg.norm(toward)
    up = np.array((0.0, 0.0, 1.0))
    return [
        target + d * (math.cos(e) * toward + math.sin(e) * up)
        for e in VIEW_ELEVATIONS
        for d in VIEW_DISTANCES
    ]


def _places(robot: ProjectedRobot, arm: str, target: np.ndarray) -> list[np.ndarray]:
    frame = robot.description.cameras[0].frame
    now = np.asarray(robot.world.link_pose(robot.name, frame).position, float)
    places = [now, *_ring(robot, arm, target)]
    return [p for p in places if float(np.linalg.norm(target - p)) > MIN_DISTANCE]


def _solve_view(robot: ProjectedRobot, arm: str, place: np.ndarray, target: np.ndarray) -> IKResult:
    frame = robot.description.cameras[0].frame
    eye = (float(place[0]), float(place[1]), float(place[2]))
    aim = (float(target[0]), float(target[1]), float(target[2]))
    view = Pose(eye, optical_look_at(eye, aim))
    target_in_base = robot.base_pose().inverse() * view
    check = collision_check(robot, arm, "avoid_all")
    options = IKOptions(frame=frame, max_restarts=VIEW_RESTARTS, random_seed=IK_RANDOM_SEED)
    seed = robot.world.joint_states(robot.name)
    with robot.ik_lock, putting_back_once(check):
        return solve_ik(
            robot.description, arm, target_in_base, seed=seed, options=options,
            collision_check=check, stop_check=checkpoint,
        )  # fmt: skip


def look_by_arm(robot: ProjectedRobot, arm: str, target_in_map: Vector3) -> dict[str, float]:
    """Move ``arm`` so the camera it carries looks at ``target_in_map``; the joints set.

    Raises:
        PtuPathBlocked: every viewing pose IK found is blocked on the way; the arm did not move.
        PtuGoalUnreachable: no viewing place has a collision-free IK solution.
    """
    target = np.asarray(target_in_map, float)
    blocked: list[ManipulationPathBlocked] = []
    places = _places(robot, arm, target)
    for place in places:
        result = _solve_view(robot, arm, place, target)
        if not result.success:
            continue
        try:
            return move_along_checked(
                robot, dict(result.joint_positions), kind="arm",
                what=f"{robot.name}'s {arm} arm (looking)", plan=True,
            )  # fmt: skip
        except ManipulationPathBlocked as failure:  # another viewing place may be free
            blocked.append(failure)
    if blocked:
        raise look_blocked(robot, target_in_map, blocked[0], f"{arm} arm") from blocked[0]
    frame = robot.description.cameras[0].frame
    raise PtuGoalUnreachable(
        f"{robot.name}'s {arm} arm cannot point its camera {frame} at {tuple(target_in_map)} "
        f"from any of {len(places)} viewing places without a collision; move the base closer",
        target=tuple(target_in_map),
    )

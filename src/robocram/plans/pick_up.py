"""Pick up an object with any robot: one plan, unchanged, on the PR2, the HSR and Boxy.

The plan asks the knowledge base for everything robot-specific (arms, tool frames, torso
limits, parking joints) and works out the gripper's approach axis from the geometry of the
hand, so the same PERFORM calls run on every robot and in every environment (projection,
recording, a real robot): only the environment around the plan changes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from robocram.designators import ObjectDesignator, a, an
from robocram.execution import perform
from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.logic import current_kb
from robocram.plans.errors import PlanSetupError
from robocram.plans.robot_facts import current_robot
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat

APPROACH = 0.10  # [m] the pre-grasp pose is this far above the grasp
LIFT = 0.10  # [m] the mug is lifted by this much
GRASP_HEIGHT = 0.05  # [m] above the mug's bottom (its frame origin)
YAWS = (0.0, math.pi, math.pi / 2, -math.pi / 2)  # [rad] grasp turns tried in order
FIXED_FRAME = "map"  # targets are kept here, since the base may move while reaching


@dataclass(frozen=True)
class PickResult:
    """What the plan did: the arm, the object and the tool targets it reached (base frame)."""

    arm: str
    tool_frame: str
    object_name: str
    grasp: PoseStamped
    lifted: PoseStamped
    detected: ObjectDesignator


def _raise_torso(robot: str) -> None:
    kb = current_kb()
    torso = kb.first("robot_torso_link_joint(R, _, J), joint_upper_limit(R, J, U)", R=robot)
    if torso is not None:
        perform(a.motion(type="moving-torso", joint_angle=torso["U"]))


def _park_arms(robot: str) -> list[str]:
    kb = current_kb()
    arms = []
    for answer in kb.query("arm(R, A), robot_arms_parking_joint_states(R, A, S)", R=robot):
        if answer["S"]:
            perform(a.motion(type="moving-arm-joints", arm=answer["A"], configuration=answer["S"]))
        arms.append(answer["A"])
    return arms


def _approach_axis(robot: str, arm: str) -> tuple[str, np.ndarray]:
    """The tool frame and its approach axis: from the wrist towards the tool frame."""
    facts = current_kb().first(
        "robot_tool_frame(R, A, T), end_effector_link(R, A, E)", R=robot, A=arm
    )
    if facts is None:
        raise PlanSetupError(
            f"pick_up found no robot_tool_frame/3 and end_effector_link/3 for arm {arm!r} of "
            f"{robot!r}; give the arm a tool frame and an end effector in its description"
        )
    wrist = transform_pose(PoseStamped(facts["E"]), facts["T"]).position
    axis = -np.asarray(wrist, float)
    return facts["T"], axis / np.linalg.norm(axis)


def _top_down(axis_in_tool: np.ndarray, yaw: float) -> quat.Quaternion:
    """Tool orientation whose approach axis points down, turned by ``yaw`` about vertical."""
    down = np.array((0.0, 0.0, -1.0))
    turn = np.cross(axis_in_tool, down)
    angle = math.atan2(float(np.linalg.norm(turn)), float(axis_in_tool @ down))
    if np.linalg.norm(turn) < 1e-9:
        turn = np.array((1.0, 0.0, 0.0))
    aligned = quat.from_axis_angle(tuple(turn / np.linalg.norm(turn)), angle)
    return quat.multiply(quat.from_euler(0.0, 0.0, yaw), aligned)


def _nearest_arm(robot: str, arms: list[str], target: PoseStamped) -> str:
    def distance(arm: str) -> float:
        tool, _ = _approach_axis(robot, arm)
        here = transform_pose(PoseStamped(tool), target.frame_id).pose
        return here.distance_to(target.pose)

    return min(arms, key=distance)


def _reach_from_above(arm: str, spot: PoseStamped, axis: np.ndarray) -> PoseStamped:
    """Move the tool above ``spot`` with the first reachable grasp turn; return the grasp."""
    failures: list[ManipulationPoseUnreachable] = []
    for yaw in YAWS:
        grasp = spot.with_frame(spot.frame_id, Pose(spot.position, _top_down(axis, yaw)))
        above = _shifted(grasp, APPROACH)
        try:
            perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=above)))
            return grasp
        except ManipulationPoseUnreachable as failure:
            failures.append(failure)
    raise failures[-1]


def _shifted(pose: PoseStamped, dz: float) -> PoseStamped:
    x, y, z = pose.position
    return pose.with_frame(pose.frame_id, Pose((x, y, z + dz), pose.orientation))


def pick_up(look_target: PoseStamped, object_type: str = "mug") -> PickResult:
    """Look, raise the torso, open, detect, grasp from above, grip and lift an object."""
    robot = current_robot()
    arms = _park_arms(robot)
    perform(a.motion(type="looking", target=a.location(pose=look_target)))
    _raise_torso(robot)
    perform(a.motion(type="looking", target=a.location(pose=look_target)))
    seen = perform(a.motion(type="detecting", object=an.object(type=object_type)))
    # in the fixed frame: an arm that reaches with the base moves the base frame
    pose = transform_pose(seen.get("pose"), FIXED_FRAME)
    arm = _nearest_arm(robot, arms, pose)
    tool, axis = _approach_axis(robot, arm)
    perform(a.motion(type="opening", gripper=arm))
    grasp = _reach_from_above(arm, _shifted(pose.with_frame(pose.frame_id), GRASP_HEIGHT), axis)
    grasping = {"collision_mode": "allow_hand"}  # the fingers close around the object
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=grasp), **grasping))
    perform(a.motion(type="gripping", gripper=arm))
    lifted = _shifted(grasp, LIFT)
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=lifted), **grasping))
    return PickResult(arm, tool, seen.get("name"), grasp, lifted, seen)

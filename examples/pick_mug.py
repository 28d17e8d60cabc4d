"""Pick up a mug with any robot: one plan, unchanged, on the PR2, the HSR and Boxy.

The plan asks the knowledge base for everything robot-specific (arms, tool frames, torso
limits, parking joints) and works out the gripper's approach axis from the geometry of
the hand, so the same PERFORM calls run on every robot; only the scene differs. Run it:
``python examples/pick_mug.py [pr2|hsrb|boxy]``.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass

import numpy as np

from robocram.designators import ObjectDesignator, a, an
from robocram.execution import perform
from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.logic import current_kb
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.tf import quaternion as quat
from robocram.world import World

APPROACH = 0.10  # [m] the pre-grasp pose is this far above the grasp
LIFT = 0.10  # [m] the mug is lifted by this much
GRASP_HEIGHT = 0.05  # [m] above the mug's bottom (its frame origin)
YAWS = (0.0, math.pi, math.pi / 2, -math.pi / 2)  # [rad] grasp turns tried in order


@dataclass(frozen=True)
class PickResult:
    """What the plan did: the arm, the object and the tool targets it reached (base frame)."""

    arm: str
    tool_frame: str
    object_name: str
    grasp: PoseStamped
    lifted: PoseStamped
    detected: ObjectDesignator


@dataclass(frozen=True)
class Scene:
    """A robot and a table with a mug, and the point on the table to look at."""

    world: World
    robot: str
    look_target: PoseStamped


def _robot_facts() -> dict[str, object]:
    kb = current_kb()
    answer = kb.first("robot(R), robot_base_frame(R, Base)")
    if answer is None:
        raise RuntimeError("no robot/1 fact in the current knowledge base; run in an environment")
    return answer


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
    assert facts is not None  # every arm has both facts
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
    last: ManipulationPoseUnreachable | None = None
    for yaw in YAWS:
        grasp = spot.with_frame(spot.frame_id, Pose(spot.position, _top_down(axis, yaw)))
        above = _shifted(grasp, APPROACH)
        try:
            perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=above)))
            return grasp
        except ManipulationPoseUnreachable as failure:
            last = failure
    assert last is not None
    raise last


def _shifted(pose: PoseStamped, dz: float) -> PoseStamped:
    x, y, z = pose.position
    return pose.with_frame(pose.frame_id, Pose((x, y, z + dz), pose.orientation))


def pick_mug(look_target: PoseStamped, object_type: str = "mug") -> PickResult:
    """Look, raise the torso, open, detect, grasp from above, grip and lift an object."""
    robot = str(_robot_facts()["R"])
    arms = _park_arms(robot)
    perform(a.motion(type="looking", target=a.location(pose=look_target)))
    _raise_torso(robot)
    perform(a.motion(type="looking", target=a.location(pose=look_target)))
    seen = perform(a.motion(type="detecting", object=an.object(type=object_type)))
    pose = seen.get("pose")
    arm = _nearest_arm(robot, arms, pose)
    tool, axis = _approach_axis(robot, arm)
    perform(a.motion(type="opening", gripper=arm))
    grasp = _reach_from_above(arm, _shifted(pose.with_frame(pose.frame_id), GRASP_HEIGHT), axis)
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=grasp)))
    perform(a.motion(type="gripping", gripper=arm))
    lifted = _shifted(grasp, LIFT)
    perform(a.motion(type="moving-tcp", arm=arm, target=a.location(pose=lifted)))
    return PickResult(arm, tool, seen.get("name"), grasp, lifted, seen)


def _within_limits(world: World, robot: str) -> None:
    """Move joints that start outside their limits (World starts every joint at 0) inside."""
    model = world.robot(robot).description.model
    assert model is not None
    joints = world.joint_states(robot)
    masters = {j: v for j, v in joints.items() if model.joints[j].mimic is None}
    inside = {j: world.joint_limits(robot, j).clamp(v) for j, v in masters.items()}
    world.set_joint_states(robot, {j: v for j, v in inside.items() if v != joints[j]})


def make_scene(robot: str) -> Scene:
    """A floor, a table and a mug placed where ``robot``'s arm can pick it from above."""
    table_height, mug_xy, robot_xy = {
        "pr2": (0.70, (0.62, -0.15), (0.0, 0.0)),
        "hsrb": (0.42, (0.46, 0.078), (0.0, 0.0)),
        "boxy": (0.55, (0.75, -0.25), (0.0, 0.0)),
    }[robot]
    world = World()
    world.add_floor()
    world.add_robot(robot, pose=Pose((*robot_xy, 0.0)))
    _within_limits(world, robot)
    tx = mug_xy[0] + 0.2
    world.add_box("table", (0.6, 1.0, table_height), pose=Pose((tx, 0.0, table_height / 2)))
    world.add_item("mug-1", "mug", pose=Pose((*mug_xy, table_height)))
    world.add_item("bottle-1", "bottle", pose=Pose((tx + 0.15, 0.3, table_height + 0.125)))
    look = PoseStamped("map", (mug_xy[0], mug_xy[1], table_height))
    return Scene(world, robot, look)


def main(robot: str = "pr2") -> None:
    """Run the plan on ``robot`` and print what happened."""
    start = time.perf_counter()
    scene = make_scene(robot)
    with simulated_robot(scene.world, robot) as run:
        result = pick_mug(scene.look_target)
    mug = scene.world.pose(result.object_name).position
    print(run.tree.render())
    print(
        f"{robot}: {result.arm} arm holds {result.object_name} at {np.round(mug, 3)} "
        f"({time.perf_counter() - start:.2f} s)"
    )


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "pr2")

"""A traced PR2 run that executes timed trajectories: an arm motion, a torso motion, a drive.

The torso moves through projection (``moving-torso``), so its trajectory is projection's.

The arm and base trajectories are timed by the motion layer on real PR2 joint paths under
the PR2's limits; the run sets the world to each trajectory's end and reports it the way
projection does (``report_executed``), inside a task of its own. The mug is held (attached
to the right gripper) before the drive, so it rides along.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from robocram.designators import a
from robocram.execution import perform, sub_task
from robocram.motion import JointTrajectory, joint_limits, report_executed, time_parameterize
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.tf.quaternion import from_euler
from robocram.traces import trace_to
from robocram.world import World

ARM_TASK, BASE_TASK = "move-arm", "move-base"
BASE_GOAL = (-0.4, 0.3, 0.6)  # [m, m, rad] in map
TORSO_GOAL = 0.1  # [m]


@dataclass
class TrajectoryRun:
    """The database, run id, the world after the run and the trajectories reported."""

    db_path: Path
    run: int
    world: World
    arm: JointTrajectory
    base: JointTrajectory


def execute(world: World, task_name: str, trajectory: JointTrajectory) -> None:
    """In a task ``task_name``: put the robot at the trajectory's end and report it."""
    with sub_task(task_name):
        end = trajectory.end
        if trajectory.kind == "base":
            pose = Pose((end["x"], end["y"], 0.0), from_euler(0.0, 0.0, end["yaw"]))
            world.set_pose(trajectory.robot, pose)
        else:
            world.set_joint_states(trajectory.robot, end)
        report_executed(trajectory)


def arm_trajectory(world: World) -> JointTrajectory:
    """The right arm from where it is, through the carrying pose, to beside the parking pose."""
    desc = world.robot("pr2").description
    arm = desc.arms["right"]
    names = arm.joints
    now = world.joint_states("pr2")
    path = [
        [now[n] for n in names],
        [arm.carrying[n] for n in names],
        [arm.parking[n] + (0.3 if n == "r_elbow_flex_joint" else 0.0) for n in names],
    ]
    return time_parameterize("pr2", names, path, joint_limits(desc, names), kind="arm")


def base_trajectory(world: World) -> JointTrajectory:
    """The base from the origin of map to :data:`BASE_GOAL`, turning on the way."""
    desc = world.robot("pr2").description
    names = ("x", "y", "yaw")
    path = [[0.0, 0.0, 0.0], [-0.2, 0.0, 0.3], list(BASE_GOAL)]
    return time_parameterize("pr2", names, path, joint_limits(desc, names), kind="base")


def traced_trajectory_run(db_path: Path) -> TrajectoryRun:
    """Trace: arm trajectory, grasp the mug, a torso motion (its trajectory and a stored
    state), drive."""
    scene = tabletop_scene("pr2")
    world = scene.world
    with (
        trace_to(db_path, world=world) as tracer,
        simulated_robot(world, "pr2", name="moves"),
    ):
        arm = arm_trajectory(world)
        execute(world, ARM_TASK, arm)
        world.attach("mug-1", "pr2", "r_gripper_tool_frame")
        perform(a.motion(type="moving-torso", joint_angle=TORSO_GOAL))
        base = base_trajectory(world)
        execute(world, BASE_TASK, base)
    return TrajectoryRun(db_path, tracer.runs[0], world, arm, base)

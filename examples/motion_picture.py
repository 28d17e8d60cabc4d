"""Draw the picture of docs/motion.md: the PR2's arm planned round a box on the counter.

The PR2 stands at the counter with its torso up and its arms parked; a box stands on the
counter where the straight joint-space move to the mug's pre-grasp would sweep the
forearm. Small spheres mark the tool frame along the executed (planned) trajectory
(green) and along the blocked straight move (red); the robot is drawn where it ends.

Usage: ``python examples/motion_picture.py [out=docs/motion_shelf.png]``
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from robocram.designators import a, an
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans import install_actions, perform
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.world import World

SHELF = ((0.12, 0.12, 0.36), (-0.97, 2.02, 1.04))  # size, centre [m]
GREEN, RED = (0.1, 0.8, 0.2, 1.0), (0.9, 0.1, 0.1, 1.0)


def looking(eye: tuple[float, float, float], target: tuple[float, float, float]) -> Pose:
    """A camera pose (optical frame: z forward, y down) at ``eye`` looking at ``target``."""
    z = np.subtract(target, eye) / np.linalg.norm(np.subtract(target, eye))
    down = -(np.array([0.0, 0.0, 1.0]) - z[2] * z)
    y = down / np.linalg.norm(down)
    x = np.cross(y, z)
    return Pose(eye, _quaternion(np.column_stack([x, y, z])))


def _quaternion(m: np.ndarray) -> tuple[float, float, float, float]:
    """The unit quaternion (x, y, z, w) of a rotation matrix (its trace is > -1 here)."""
    w = math.sqrt(max(0.0, 1.0 + m[0, 0] + m[1, 1] + m[2, 2])) / 2.0
    if w < 1e-6:
        raise ValueError("a camera turned half round about an axis; look from elsewhere")
    return ((m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w),
            (m[1, 0] - m[0, 1]) / (4 * w), w)  # fmt: skip


def _tool_positions(world: World, trajectory: JointTrajectory, frame: str, count: int) -> list:
    end = world.joint_states("pr2")
    positions = []
    for t in np.linspace(0.0, trajectory.duration, count):
        values = zip(trajectory.joint_names, trajectory.at(t), strict=True)
        world.set_joint_states("pr2", dict(values))
        positions.append(world.link_pose("pr2", frame).position)
    world.set_joint_states("pr2", end)
    return positions


def draw(path: Path) -> Path:
    """Plan and execute the motion round the box, mark the paths, render."""
    scene = kitchen_scene("pr2")
    world = scene.world
    x = world.pose("mug-1").position[0]
    executed: list[JointTrajectory] = []
    install_actions(world.kb)
    north = (0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4))  # facing +y
    stand = PoseStamped("map", (x, 1.43, 0.0), north)
    with simulated_robot(world, "pr2"):
        perform(an.action(type="parking-arms"))
        perform(an.action(type="moving-torso", joint_angle="upper"))
        perform(an.action(type="navigating", target=stand))
        grasp = world.kb.first("object_grasp(O, R, A, N, G, P, L)", O="mug-1", R="pr2", A="right")
        world.add_box("shelf", *SHELF, color=(0.55, 0.35, 0.2, 1.0))
        with trajectory_listener(executed.append):
            perform(a.motion(type="moving-tcp", arm="right", target=a.location(pose=grasp["P"])))
    planned = executed[-1]
    tool = world.robot("pr2").description.arms["right"].tool_frame
    straight = JointTrajectory("pr2", planned.joint_names, (planned.points[0], planned.points[-1]))
    for k, where in enumerate(_tool_positions(world, planned, tool, 40)):
        world.bodies.add_sphere(f"planned-{k}", 0.012, Pose(where), color=GREEN)
    for k, where in enumerate(_tool_positions(world, straight, tool, 25)):
        world.bodies.add_sphere(f"straight-{k}", 0.01, Pose(where), color=RED)
    camera = looking((-1.9, 1.0, 2.1), (-1.0, 1.95, 1.05))
    out = world.view.save_png(path, camera, width=800, height=600)
    world.close()
    return out


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("docs/motion_shelf.png")
    print(draw(target))

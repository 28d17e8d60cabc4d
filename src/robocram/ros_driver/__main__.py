"""Run the projection driver as a ROS node on a scene (tabletop or kitchen) of a robot.

``python -m robocram.ros_driver --robot pr2 --master-uri http://127.0.0.1:11311
[--scene kitchen]`` (or ``--ros 2 [--domain-id N]`` for ROS 2) prints
``ready <node name>`` on stdout once its action servers run, then serves until killed
(SIGTERM or SIGINT) or the master goes away. Its standard input takes resets
(``driver_reset.py``).
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from robocram.robots import RobotDescription, load_description
from robocram.ros.ros_config import install_ros_facts, read_ros_config
from robocram.ros_driver.driver_reset import serve_resets
from robocram.ros_driver.motion import MotionOptions
from robocram.ros_driver.projection_driver import CONTROLLERS, FAULTS, ProjectionDriver
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.world import World

SCENES = ("tabletop", "kitchen")


def _build_scene(scene: str, robot: str | RobotDescription, world: World) -> str:
    """Build ``scene`` with ``robot`` in ``world``; return the robot's name there."""
    if scene == "kitchen":
        return kitchen_scene(robot, world).robot
    return tabletop_scene(robot, world).robot


def _arguments() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--robot", default="pr2", help="built-in robot: pr2, hsrb")
    parser.add_argument("--master-uri", default=os.environ.get("ROS_MASTER_URI", ""))
    parser.add_argument("--scene", choices=SCENES, default="tabletop")
    parser.add_argument("--ros-facts", type=Path, help="ROS facts file (default: packaged)")
    parser.add_argument("--base-speed", type=float, default=0.5, help="[m/s]; 0 jumps")
    parser.add_argument("--time-scale", type=float, default=1.0, help="trajectory time x")
    parser.add_argument("--fault", choices=FAULTS, default="none")
    parser.add_argument("--node-name", default="robocram_driver")
    parser.add_argument("--goal-log", type=Path, help="append each goal received as JSON")
    parser.add_argument(
        "--controllers", choices=CONTROLLERS, default="projection", help="pr2: the real PR2's"
    )
    parser.add_argument("--clock-offset", type=float, default=0.0, help="[s] added to stamps")
    parser.add_argument("--tf-lag", type=float, default=0.0, help="[s] /tf sent late (tests)")
    parser.add_argument("--ros", type=int, choices=(1, 2), default=1, help="ROS 1 or ROS 2")
    parser.add_argument(
        "--domain-id", type=int, default=int(os.environ.get("ROS_DOMAIN_ID", 0)), help="ROS 2"
    )
    return parser.parse_args()


def main() -> None:
    """Build the scene, join ROS, serve."""
    args = _arguments()
    if args.ros == 2:
        from robocram.ros_driver.ros2_main import ros2_main

        ros2_main(args, _build_scene)
        return
    if not args.master_uri:
        raise SystemExit("give --master-uri or set ROS_MASTER_URI")
    os.environ["ROS_MASTER_URI"] = args.master_uri
    import rospy

    world = World()
    robot = _build_scene(args.scene, args.robot, world)
    facts = args.ros_facts.read_text() if args.ros_facts else None
    install_ros_facts(world.kb, robot, facts)
    config = read_ros_config(world.kb, load_description(robot))
    options = MotionOptions(base_speed=args.base_speed, time_scale=args.time_scale)
    rospy.init_node(args.node_name)
    driver = ProjectionDriver(
        world,
        config,
        options,
        args.fault,
        args.goal_log,
        args.controllers,
        args.clock_offset,
        args.tf_lag,
    )
    driver.start()
    driver.publish_state()
    serve_resets(driver.reset)
    print("ready", rospy.get_name(), flush=True)
    rospy.spin()


if __name__ == "__main__":
    main()

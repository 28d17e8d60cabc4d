"""``python -m robocram.ros_driver --ros 2``: the projection driver as a ROS 2 node.

Started from the venv (where ROS 1 is on the path and rclpy is not), it runs itself
again in the ROS 2 prefix's environment (``ros2_environment.py``); there it builds the
scene, serves it (``ros2_driver.py``) and prints ``ready <node name>`` once its action
servers run, until SIGTERM or SIGINT, taking resets on its standard input (``driver_reset.py``).
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
import threading
from collections.abc import Callable
from typing import TYPE_CHECKING

from robocram.robots import RobotDescription, load_description
from robocram.ros.ros2_environment import child_argv, require_ros2
from robocram.ros.ros_config import install_ros_facts, read_ros_config
from robocram.ros_driver.driver_reset import serve_resets
from robocram.ros_driver.motion import MotionOptions
from robocram.world import World

if TYPE_CHECKING:
    from robocram.ros_driver.ros2_driver import Ros2ProjectionDriver

RUN_AGAIN = "import runpy; runpy.run_module('robocram.ros_driver', run_name='__main__')"


def ros2_main(
    args: argparse.Namespace, build_scene: Callable[[str, str | RobotDescription, World], str]
) -> None:
    """Build the scene, join ROS 2 on ``args.domain_id``, serve."""
    if importlib.util.find_spec("rclpy") is None:  # in the venv: again, in ROS 2's environment
        environment = require_ros2().environment(args.domain_id)
        os.execve(sys.executable, [*child_argv(RUN_AGAIN), *sys.argv[1:]], environment)
    import rclpy

    from robocram.ros_driver.ros2_driver import Ros2ProjectionDriver, serve

    world = World()
    desc = load_description(args.robot)  # a built-in's name or a description file
    robot = build_scene(args.scene, desc, world)
    facts = args.ros_facts.read_text() if args.ros_facts else None
    install_ros_facts(world.kb, robot, facts, ros=2)
    config = read_ros_config(world.kb, desc)
    options = MotionOptions(base_speed=args.base_speed, time_scale=args.time_scale)
    driver = Ros2ProjectionDriver(
        world, config, options, args.fault, args.goal_log, args.controllers, args.clock_offset
    )
    rclpy.init()
    node = rclpy.create_node(args.node_name)
    ready = threading.Event()
    announce = threading.Thread(target=_announce, args=(ready, node, driver), daemon=True)
    announce.start()
    try:
        serve(driver, node, ready)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


def _announce(ready: threading.Event, node: object, driver: Ros2ProjectionDriver) -> None:
    """Say the node is ready, then take resets (``driver_reset.py``)."""
    ready.wait()
    print("ready", node.get_fully_qualified_name(), flush=True)  # type: ignore[attr-defined]
    serve_resets(driver.reset)

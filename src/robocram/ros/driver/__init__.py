"""A ROS driver of ours that serves a robot's interfaces by driving a projection world.

Start it as a node: ``python -m robocram.ros.driver --robot pr2 --master-uri URI``.
"""

from robocram.ros.driver.motion import MotionOptions
from robocram.ros.driver.projection_driver import FAULTS, ProjectionDriver

__all__ = ["FAULTS", "MotionOptions", "ProjectionDriver"]

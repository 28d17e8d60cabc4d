"""A ROS driver of ours that serves a robot's interfaces by driving a projection world.

Start it as a node: ``python -m robocram.ros_driver --robot pr2 --master-uri URI``. It is
a layer of its own above ``ros`` and ``projection``: the real-robot code in ``ros`` never
depends on the simulator; this test and demo robot behind ROS does.
"""

from robocram.ros_driver.motion import MotionOptions
from robocram.ros_driver.projection_driver import FAULTS, ProjectionDriver

__all__ = ["FAULTS", "MotionOptions", "ProjectionDriver"]

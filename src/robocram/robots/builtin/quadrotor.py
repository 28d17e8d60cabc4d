"""The hector quadrotor, from the PyPI package ``example-robot-data``: one link, no arms.

It flies, so its base frame is the body itself (``base_link``), not a floor projection.
"""

from __future__ import annotations

from robocram.robots.description import RobotDescription
from robocram.robots.example_robot_data import example_robot_data_folder


def description() -> RobotDescription:
    """The quadrotor's description (unchecked; ``load_description("quadrotor")`` checks it)."""
    return RobotDescription(
        name="quadrotor",
        urdf=example_robot_data_folder() / "hector_description" / "robots" / "quadrotor_base.urdf",
        base_frame="base_link",
        odom_frame="odom",
        flying=True,
    )

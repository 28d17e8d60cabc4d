"""The tutorial turtle: a 2-D simulator, its process modules, plans and environments.

``TurtleWorld`` is an 11 x 11 field with a turtle and a pen; ``turtle_environment(world)``
grounds ``driving``, ``moving`` and ``setting-pen`` motions and ``navigating`` and
``drawing`` actions for it; ``noisy_turtle_environment`` runs the same plans on a less
exact turtle. ``voice_environment`` is a robot with no body: it says and listens.
"""

from robocram.turtlesim.controller import GoToGains, go_to
from robocram.turtlesim.environment import (
    noisy_turtle_environment,
    turtle_environment,
    turtle_knowledge_base,
)
from robocram.turtlesim.fluents import out_of_bounds_fluent, pose_fluent
from robocram.turtlesim.locations import turtle_location_resolver
from robocram.turtlesim.plans import draw_house, house_corners, navigate
from robocram.turtlesim.process_modules import (
    NoisyTurtleNavigationPM,
    TurtleNavigationPM,
    TurtlePenPM,
)
from robocram.turtlesim.voice import NothingHeard, VoicePM, voice_environment
from robocram.turtlesim.world import Line, TurtlePose, TurtleWorld

__all__ = [
    "GoToGains",
    "Line",
    "NoisyTurtleNavigationPM",
    "NothingHeard",
    "TurtleNavigationPM",
    "TurtlePenPM",
    "TurtlePose",
    "TurtleWorld",
    "VoicePM",
    "draw_house",
    "go_to",
    "house_corners",
    "navigate",
    "noisy_turtle_environment",
    "out_of_bounds_fluent",
    "pose_fluent",
    "turtle_environment",
    "turtle_knowledge_base",
    "turtle_location_resolver",
    "voice_environment",
]

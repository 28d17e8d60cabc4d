"""The projection environment of one robot: its process modules and the facts choosing them.

``projection_environment(world, robot)`` builds an :class:`Environment` on the world's
knowledge base (world predicates and the robot's description facts are already there),
adds the motion groundings of the motion table (common ones, flying ones for flying
robots, legged ones for robots on legs they bend) and one process module per resource the
robot has (``RobotDescription.resources()``, ``ptu`` where an arm or a pan joint turns the
camera: ``looking_means.py``, and ``legs`` for a legged robot: ``crouching.py``), with
the ``matching_process_module/2`` facts the table gives for those resources. The grasp
model answers ``object_grasp/7`` and its siblings (``robocram.grasping``,
docs/grasping.md) so plans reach grasps through the KB.
Location designators resolve through costmaps
(:class:`~robocram.costmaps.CostmapLocations` on the same world), so ``visible_for``,
``reachable_for``, ``on`` and the other keys work in any projected plan.
"""

from __future__ import annotations

from robocram.costmaps import CostmapLocations
from robocram.designators import install_motion_family
from robocram.execution import Environment, matching_facts
from robocram.grasping import install_grasp_predicates
from robocram.logic import KnowledgeBase
from robocram.motion import MotionSettings
from robocram.projection.crouching import can_crouch
from robocram.projection.process_modules import PROJECTION_MODULES
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import LoadedDescription, RobotDescription
from robocram.robots.looking_means import with_looking
from robocram.world import RobotObject, World

PREFIX = "projection"  # module atoms: projection_arms, projection_ptu, ...


def install_motions(kb: KnowledgeBase, desc: RobotDescription) -> KnowledgeBase:
    """Install the motion groundings ``desc``'s robot understands into ``kb``."""
    install_motion_family(kb, "common")
    if desc.flying:
        install_motion_family(kb, "flying")
    if isinstance(desc, LoadedDescription) and can_crouch(desc):
        install_motion_family(kb, "legged")
    return kb


def with_legs(desc: RobotDescription, resources: tuple[str, ...]) -> tuple[str, ...]:
    """``resources`` and, for a robot on legs it bends, ``legs`` (crouching)."""
    legged = isinstance(desc, LoadedDescription) and can_crouch(desc)
    return (*resources, "legs") if legged else resources


def with_tools(resources: tuple[str, ...]) -> tuple[str, ...]:
    """``resources`` and, where the robot has arms, ``tools`` (held tools along paths)."""
    return (*resources, "tools") if "arms" in resources else resources


def projection_environment(
    world: World,
    robot: str | RobotObject | None = None,
    locations: CostmapLocations | None = None,
    motion: MotionSettings | None = None,
) -> Environment:
    """The environment whose process modules act on ``robot`` (default: the only robot).

    ``locations`` resolves location designators (default: costmaps on ``world``, seed 0);
    ``motion`` says how arm motions are planned (default: round obstacles, seed 0).
    """
    projected = ProjectedRobot.of(world, robot, motion)
    desc = projected.description
    resources = with_legs(desc, with_tools(with_looking(desc, desc.resources())))
    kb = install_motions(world.kb, desc)
    install_grasp_predicates(kb, world)
    return Environment(
        f"{PREFIX}_{projected.name}",
        process_modules=[PROJECTION_MODULES[r](projected) for r in resources],
        facts=matching_facts(PREFIX, resources),
        kb=kb,
        location_resolver=(locations or CostmapLocations(world)).resolver(),
    )

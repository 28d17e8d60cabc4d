"""The projection environment of one robot: its process modules and the facts choosing them.

``projection_environment(world, robot)`` builds an :class:`Environment` on the world's
knowledge base (world predicates and the robot's description facts are already there),
adds the common motion groundings (and ``flying.pl`` for flying robots) and says which
process module handles which motion type: ``matching_process_module/2`` and
``available_process_module/1`` facts, one module per resource the robot has.
"""

from __future__ import annotations

from importlib import resources

from robocram.designators import install_common_motions
from robocram.execution import Environment
from robocram.logic import KnowledgeBase
from robocram.projection.process_modules import (
    ArmPM,
    DistanceSensorPM,
    FlyingPM,
    GripperPM,
    NavigationPM,
    PerceptionPM,
    ProjectionProcessModule,
    PtuPM,
    TorsoPM,
)
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots import RobotDescription
from robocram.world import RobotObject, World

FLYING_GROUP = "projection_flying_motions"

MOTION_TYPES: dict[type[ProjectionProcessModule], tuple[str, ...]] = {
    NavigationPM: ("going",),
    TorsoPM: ("moving-torso",),
    PtuPM: ("looking",),
    PerceptionPM: ("detecting",),
    GripperPM: ("opening", "closing", "gripping", "moving-gripper-joint"),
    ArmPM: ("moving-tcp", "moving-arm-joints"),
    FlyingPM: ("flying",),
    DistanceSensorPM: ("distance-sensing",),
}


def module_classes(desc: RobotDescription) -> list[type[ProjectionProcessModule]]:
    """The process module classes for the resources ``desc`` has."""
    if desc.flying:
        return [FlyingPM, DistanceSensorPM, *([PerceptionPM] if desc.cameras else [])]
    classes: list[type[ProjectionProcessModule]] = [NavigationPM]
    if desc.torso_joint is not None:
        classes.append(TorsoPM)
    if desc.cameras:
        classes.append(PerceptionPM)
        if desc.pan_tilt is not None or desc.neck_arm is not None:
            classes.append(PtuPM)
    if any(name != desc.neck_arm for name in desc.arms):
        classes += [GripperPM, ArmPM]
    return classes


def module_name(cls: type[ProjectionProcessModule], prefix: str = "projection") -> str:
    """The module atom for ``cls``'s resource: ``projection_arms``, ``recorded_arms``, ..."""
    return f"{prefix}_{cls.name.removeprefix('projection_')}"


def matching_facts(classes: list[type[ProjectionProcessModule]], prefix: str = "projection") -> str:
    """Prolog facts sending each motion type to its module, and marking modules available."""
    lines = []
    for cls in classes:
        pm = module_name(cls, prefix)
        for motion in MOTION_TYPES[cls]:
            lines.append(f"matching_process_module(D, {pm}) :- desig_prop(D, type, '{motion}').")
        lines.append(f"available_process_module({pm}).")
    return "\n".join(lines) + "\n"


def install_motions(kb: KnowledgeBase, desc: RobotDescription) -> KnowledgeBase:
    """Install the motion groundings ``desc``'s robot understands into ``kb``."""
    install_common_motions(kb)
    if desc.flying:
        text = resources.files("robocram.projection").joinpath("flying.pl").read_text()
        kb.consult(text, group=FLYING_GROUP)
    return kb


def projection_environment(world: World, robot: str | RobotObject | None = None) -> Environment:
    """The environment whose process modules act on ``robot`` (default: the only robot)."""
    projected = ProjectedRobot.of(world, robot)
    desc = projected.description
    classes = module_classes(desc)
    kb = install_motions(world.kb, desc)
    return Environment(
        f"projection_{projected.name}",
        process_modules=[cls(projected) for cls in classes],
        facts=matching_facts(classes),
        kb=kb,
    )

"""A kitchen scene: robocram's kitchen, a robot in the middle and catalogue items in their places.

The kitchen is one articulated body (``tools/make_kitchen_urdf.py``). Its description is
drafted from that URDF like any environment's (:func:`draft_environment`: surfaces,
containers with their joint, handle and opening); only where each item type is usually
kept comes from :data:`PLACES`. The facts join the world's knowledge base as the fact
group ``kitchen_semantics``, so plans ask the KB and never hard-code a link name. Items
are placed relative to a link's frame, so moving a unit in the generator moves what
stands on it.
"""

from __future__ import annotations

from dataclasses import replace
from functools import cache
from importlib import resources
from pathlib import Path

from robocram.robots import RobotDescription, load_description
from robocram.robots.disk_cache import file_key
from robocram.robots.kept_object import kept_object
from robocram.scenes.environment_description import EnvironmentDescription
from robocram.scenes.environment_draft import draft_environment
from robocram.scenes.environment_scene import EnvironmentScene, ItemPlace, environment_scene
from robocram.scenes.errors import UnfitRobotError
from robocram.tf import Pose
from robocram.world import World

KITCHEN = "kitchen"  # the kitchen's object name, the Env of its facts
KitchenScene = EnvironmentScene  # the kitchen scene is an environment scene
# the modules whose code drafts an environment (tests/scenes check the draft runs no other)
DRAFTED_BY = (
    "robocram.robots.disk_cache",
    "robocram.robots.kept_object",
    "robocram.robots.kept_urdf",
    "robocram.robots.model_memo",
    "robocram.robots.model_split",
    "robocram.robots.package_resolver",
    "robocram.robots.robot_model",
    "robocram.robots.safe_xml",
    "robocram.robots.stand_in_palm",
    "robocram.robots.stand_in_size",
    "robocram.robots.urdf_elements",
    "robocram.robots.urdf_reader",
    "robocram.scenes.environment_description",
    "robocram.scenes.environment_draft",
    "robocram.scenes.environment_model",
    "robocram.scenes.stand_in_draft",
    "robocram.tf.pose",
    "robocram.tf.quaternion",
    "robocram.world.robot_urdf",
)
ROBOT_START = Pose((-0.8, 0.2, 0.0), (0.0, 0.0, 0.7071067811865476, 0.7071067811865476))


# Unit frames have x out of the front, so negative x is inside a drawer or behind an edge.
PLACES = (
    ItemPlace("mug-1", "mug", "counter_top_north", (0.15, -0.08)),
    ItemPlace("cereal-1", "cereal_box", "counter_top_east", (0.0, 0.3)),
    ItemPlace("milk-1", "milk", "counter_top_east", (0.0, -0.3)),
    ItemPlace("bowl-1", "bowl", "drawer_unit_drawer_3", (-0.26, 0.0)),  # seen over the front
    ItemPlace("cup-1", "cup", "cutlery_unit_drawer_4", (-0.14, 0.0)),
)


def kitchen_urdf() -> Path:
    """The generated kitchen URDF shipped with the package."""
    return Path(str(resources.files("robocram.scenes") / "data" / "kitchen.urdf"))


@cache
def kitchen_description() -> EnvironmentDescription:
    """The built-in kitchen's description: drafted from its URDF, as any environment's is.

    Nothing is written by hand but the usual places, which follow :data:`PLACES`. The
    draft (~70 ms) is kept on disk by the URDF's content and the drafting code.
    """
    urdf = kitchen_urdf()
    drafted = kept_object(
        "environment-drafts", f"{urdf} {file_key(urdf)} {KITCHEN}", DRAFTED_BY,
        lambda: draft_environment(urdf, name=KITCHEN).description, EnvironmentDescription,
    )  # fmt: skip
    usual = tuple(sorted({(p.kind, p.link) for p in PLACES}))
    return replace(drafted, usual_locations=usual)


def kitchen_scene(robot: str | RobotDescription, world: World | None = None) -> KitchenScene:
    """Floor, kitchen, ``robot`` (arms parked) in the middle facing the north counter, items.

    ``robot`` is a built-in robot's name, a description file or a ``RobotDescription``.

    Raises:
        UnfitRobotError: its base is fixed: a kitchen transport drives between counters.
    """
    desc = load_description(robot)
    if desc.drive == "fixed":
        raise UnfitRobotError(
            desc.name,
            "its base is fixed (base_type='fixed') and a kitchen transport drives between "
            "counters: mount it on a mobile base (base_type), or carry things across its "
            "table in the workcell scene (workcell_scene)",
        )
    return environment_scene(kitchen_description(), robot, PLACES, ROBOT_START, world)

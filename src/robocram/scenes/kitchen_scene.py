"""A kitchen scene: robocram's kitchen, a robot in the middle and catalogue items in their places.

The kitchen is one articulated body (``tools/make_kitchen_urdf.py``); its semantic facts
(supporting surfaces, containers with their joint and handle) join the world's knowledge
base as the fact group ``kitchen_semantics``, and where each item type is usually kept as
``kitchen_contents`` (``usual_location(Type, Env, Link)``), so plans ask the KB and never
hard-code a link name. Items are placed relative to a link's frame, so moving a unit in
the generator moves what stands on it.
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from robocram.robots import RobotDescription, load_description
from robocram.scenes.errors import SceneError
from robocram.scenes.parking import park_arms
from robocram.tf import Pose, PoseStamped
from robocram.world import World, WorldObject

KITCHEN = "kitchen"  # the kitchen's object name, the Env of its facts
RESTING_GAP = 0.002  # [m] items are put this far above their support
ROBOT_START = Pose((-0.8, 0.2, 0.0), (0.0, 0.0, 0.7071067811865476, 0.7071067811865476))


@dataclass(frozen=True)
class ItemPlace:
    """An item ``name`` of catalogue ``kind`` at ``xy`` [m] in ``link``'s frame, on its top."""

    name: str
    kind: str
    link: str
    xy: tuple[float, float]


# Unit frames have x out of the front, so negative x is inside a drawer or behind an edge.
PLACES = (
    ItemPlace("mug-1", "mug", "counter_top_north", (0.15, -0.08)),
    ItemPlace("cereal-1", "cereal_box", "counter_top_east", (0.0, 0.3)),
    ItemPlace("milk-1", "milk", "counter_top_east", (0.0, -0.3)),
    ItemPlace("bowl-1", "bowl", "drawer_unit_drawer_3", (-0.26, 0.0)),  # seen over the front
    ItemPlace("cup-1", "cup", "cutlery_unit_drawer_4", (-0.14, 0.0)),
)


@dataclass(frozen=True)
class KitchenScene:
    """The world, the robot's and the kitchen's object names, and the items by name."""

    world: World
    robot: str
    kitchen: str
    items: dict[str, WorldObject]

    @property
    def look_target(self) -> PoseStamped:
        """Where the first item (the mug on the counter) is now: what a plan that starts by
        looking looks at, as on the tabletop."""
        first = next(iter(self.items.values()))
        return PoseStamped("map", self.world.pose(first).position)


def kitchen_urdf() -> Path:
    """The generated kitchen URDF shipped with the package."""
    return Path(str(resources.files("robocram.scenes") / "data" / "kitchen.urdf"))


def kitchen_facts() -> str:
    """The kitchen's semantic facts (Prolog text) shipped with the package."""
    return (resources.files("robocram.scenes") / "data" / "kitchen.pl").read_text("utf-8")


def _place(world: World, place: ItemPlace) -> WorldObject:
    """Put the item on the top face of ``place.link`` (its floor, for a drawer)."""
    spot = world.link_pose(KITCHEN, place.link) * Pose((*place.xy, 0.0))
    top = _support_top(world, place.link, spot)
    item = world.add_item(place.name, place.kind, Pose((0.0, 0.0, 100.0)))
    below_origin = 100.0 - world.aabb(item)[0][2]  # [m] from the item's origin down
    x, y, _ = spot.position
    world.set_pose(item, Pose((x, y, top + below_origin + RESTING_GAP)))
    return item


def _support_top(world: World, link: str, spot: Pose) -> float:
    """Height [m] of the first surface of ``link`` below ``spot`` (a ray cast down)."""
    x, y, _ = spot.position
    _, high = world.link_aabb(KITCHEN, link)
    hit = world.ray_cast((x, y, high[2] + 0.01), (x, y, high[2] - 1.0))
    if hit is None or hit.link != link:
        raise SceneError(f"no surface of {link!r} under ({x:.2f}, {y:.2f}) m; fix PLACES")
    return float(hit.position[2])


def kitchen_scene(robot: str | RobotDescription, world: World | None = None) -> KitchenScene:
    """Floor, kitchen, ``robot`` in the middle facing the north counter, items in place."""
    desc = load_description(robot)
    world = world if world is not None else World()
    world.add_floor()
    world.add_urdf(KITCHEN, kitchen_urdf(), type="kitchen")
    world.kb.consult(kitchen_facts(), group="kitchen_semantics")
    name = world.add_robot(desc, pose=ROBOT_START).name
    park_arms(world, name)
    items = {p.name: _place(world, p) for p in PLACES}
    usual = sorted({f"usual_location({p.kind}, {KITCHEN}, {p.link})." for p in PLACES})
    world.kb.consult("\n".join(usual), group="kitchen_contents")
    return KitchenScene(world, name, KITCHEN, items)

"""A scene from any environment description: floor, environment, robot (arms parked), items.

The environment's facts (:meth:`EnvironmentDescription.facts`) join the world's knowledge
base as the fact group ``<name>_semantics``; each item is put on the top face of a link
(a surface, or a drawer's floor) at ``xy`` in that link's frame, and its type's usual
place is that link (group ``<name>_contents``) unless the description says otherwise.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from robocram.logic import name_atom
from robocram.robots import RobotDescription, RobotModel, load_description
from robocram.scenes.environment_description import EnvironmentDescription
from robocram.scenes.environment_model import check_urdf, loadable_urdf
from robocram.scenes.errors import SceneError
from robocram.scenes.scene_robot import place_robot
from robocram.tf import Pose, PoseLike, PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import World, WorldObject

RESTING_GAP = 0.002  # [m] items are put this far above their support
OVERLAP = 0.001  # [m] an item placed deeper than this into anything is refused
ORIGIN = Pose()


@dataclass(frozen=True)
class ItemPlace:
    """An item ``name`` of catalogue ``kind`` at ``xy`` [m] in ``link``'s frame, on its top.

    ``below`` [m], in the link's frame, puts it on the first face under that height instead
    (a shelf inside a closed cabinet, whose top is the cabinet's roof). ``yaw`` [rad] turns
    it about the vertical from the link's axes (a knife laid along a drawer's width in any
    drawer); None keeps it square to the map's.
    """

    name: str
    kind: str
    link: str
    xy: tuple[float, float]
    below: float | None = None
    yaw: float | None = None


@dataclass(frozen=True)
class EnvironmentScene:
    """The world, the robot's and the environment's object names, and the items by name."""

    world: World
    robot: str
    environment: str
    items: dict[str, WorldObject]
    # the environment's URDF as the scene's check parsed it, held so that a scene built
    # while this one lives shares the parse (the model memo holds models only weakly)
    checked: RobotModel | None = field(default=None, compare=False, repr=False)

    @property
    def kitchen(self) -> str:
        """The environment's object name (the kitchen scene's name for it)."""
        return self.environment

    @property
    def look_target(self) -> PoseStamped:
        """Where the first item is now: what a plan that starts by looking looks at."""
        first = next(iter(self.items.values()))
        return PoseStamped("map", self.world.pose(first).position)


def environment_scene(
    environment: EnvironmentDescription,
    robot: str | RobotDescription,
    items: Iterable[ItemPlace] = (),
    robot_pose: PoseLike = ORIGIN,
    world: World | None = None,
) -> EnvironmentScene:
    """Floor, ``environment`` at the origin, ``robot`` at ``robot_pose`` with parked arms, items.

    Raises:
        SceneError: an item's link has no surface under its spot.
    """
    desc = load_description(robot)
    world = world if world is not None else World()
    world.bodies.add_floor()
    name = environment.name
    checked = check_urdf(Path(environment.urdf), tuple(environment.package_paths))
    loadable = loadable_urdf(
        environment.urdf, environment.stand_ins, package_paths=environment.package_paths
    )
    world.add_urdf(name, loadable, type="environment")
    world.kb.consult(environment.facts(name), group=f"{name}_semantics")
    robot_name = place_robot(world, desc, Pose.coerce(robot_pose))
    placed = list(items)
    objects = {p.name: place_item(world, name, p) for p in placed}
    usual = usual_location_facts(environment, placed, name)
    if usual:
        world.kb.consult(usual, group=f"{name}_contents")
    return EnvironmentScene(world, robot_name, name, objects, checked)


def usual_location_facts(
    environment: EnvironmentDescription, placed: Iterable[ItemPlace], name: str
) -> str:
    """The ``usual_location/3`` facts (Prolog text) of items whose kind has no usual place.

    Every name is written by :func:`name_atom`, so a link named ``X`` stays that link.
    """
    known = {kind for kind, _ in environment.usual_locations}
    env = name_atom(name)
    usual = {
        f"usual_location({name_atom(p.kind)}, {env}, {name_atom(p.link)})."
        for p in placed
        if p.kind not in known
    }
    return "".join(f"{fact}\n" for fact in sorted(usual))


def place_item(world: World, environment: str, place: ItemPlace) -> WorldObject:
    """Put the item on the top face of ``place.link`` (its floor, for a drawer).

    Raises:
        SceneError: the item would start inside something (a knife 0.22 m long laid
            square to the map across a drawer's front): named, with what to change.
    """
    link = world.link_pose(environment, place.link)
    spot = link * Pose((*place.xy, 0.0))
    top = support_top(world, environment, place.link, spot, place.below)
    turn = Pose()
    if place.yaw is not None:
        turn = Pose(
            orientation=quat.from_euler(0.0, 0.0, quat.to_euler(link.orientation)[2] + place.yaw)
        )
    item = world.add_item(place.name, place.kind, Pose((0.0, 0.0, 100.0), turn.orientation))
    below_origin = 100.0 - world.aabb(item)[0][2]  # [m] from the item's origin down
    x, y, _ = spot.position
    world.set_pose(item, Pose((x, y, top + below_origin + RESTING_GAP), turn.orientation))
    _refuse_overlap(world, place)
    return item


def _refuse_overlap(world: World, place: ItemPlace) -> None:
    """Raise if the item just placed goes deeper than :data:`OVERLAP` into anything."""
    for _, other, other_link, gap in world.contacts.link_distances(place.name, distance=0.0):
        if gap < -OVERLAP:
            where = f"{other.name}/{other_link}" if other_link != other.name else other.name
            raise SceneError(
                f"{place.name} at {place.xy} on {place.link!r} would start {-gap * 1000:.1f} mm "
                f"inside {where}; move it (xy) or turn it (yaw)"
            )


def support_top(
    world: World, environment: str, link: str, spot: Pose, below: float | None = None
) -> float:
    """Height [m] of the first surface of ``link`` below ``spot`` (a ray cast down from
    over the link, or from ``below`` [m] over ``spot``, which is at the link frame's height)."""
    x, y, z = spot.position
    _, high = world.contacts.link_aabb(environment, link)
    start = high[2] + 0.01 if below is None else z + below
    hit = world.view.ray_cast((x, y, start), (x, y, start - 1.01))
    if hit is None or hit.link != link:
        raise SceneError(
            f"no surface of {link!r} under ({x:.2f}, {y:.2f}) m; put the item elsewhere on it"
        )
    return float(hit.position[2])

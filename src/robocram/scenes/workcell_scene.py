"""A workcell scene: a robot mounted where it works, a table in front of it, a mug and a bowl.

A lone arm (``base_type="fixed"``) cannot drive a mug across a kitchen, but it can carry
things from one spot of its table to another. The table, the robot's stand and the mug
are placed as in the tabletop scene (:mod:`robocram.scenes.placement`: from the arm's
reach, never by robot name); the table is an environment with one surface, so the same
``transport`` plan (search, fetch, deliver) runs as in the kitchen, the robot standing
where it is mounted. A robot whose fixed camera looks onto its own top (Tracy: two arms on
a table, :mod:`~robocram.scenes.own_top`) works there: its table is a thin plate a hair
over that top, just round the items' spots, so the robot's own links never touch it.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from robocram.robots import RobotDescription
from robocram.scenes.environment_description import EnvironmentDescription, SurfaceDescription
from robocram.scenes.environment_scene import (
    EnvironmentScene,
    ItemPlace,
    place_item,
    usual_location_facts,
)
from robocram.scenes.errors import UnfitRobotError
from robocram.scenes.handle_turn import turn_handle_to_arm
from robocram.scenes.placement import (
    MUG_INSET,
    TABLE_DEPTH,
    grasp_in_reach_x,
    placement_arm,
)
from robocram.scenes.table_robot import robot_at_a_table
from robocram.tf import Pose, PoseStamped, Vector3
from robocram.world import World

WORKCELL = "workcell"  # the table's object name, the Env of its facts
TABLE_TOP = "table_top"  # its one link: the surface
TABLE_WIDTH = 1.0  # [m] along y, at least: wider for a long arm's spots
SPREAD = 0.25  # of the mug's distance ahead: the bowl lies this far right of the mug
MIN_SPREAD = 0.15  # [m] at least: the bowl's rim (0.08 m) clear of the mug (0.044 m) and a hand
ASIDE_SHARE = 0.95  # of the arm's reach past the rise at its shoulder: a spot aside whose
# grasping wrist lies beyond it comes in to where the mug's does (placement.PAST_RISE_SHARE):
# the SO-101 carries its bowl 0.935 of it out; the SO-100's spots lay 0.99 and 1.01 out
FRAME_BELOW_TOP = 0.1  # [m] a search looks this far over a place's frame (search.LOOK_ABOVE):
# so at the table's top, as the pick-up does; higher, a small arm's wrist camera hits its shoulder
PLATE_THICKNESS = 0.01  # [m] of the plate the items lie on where the robot's top is its table
PLATE_HAIR = 0.002  # [m] between the robot's top and the plate: they do not touch
PLATE_MARGIN = 0.15  # [m] of plate round the items' spots: the bowl's rim (0.08 m) and a hand
URDF_FOLDER = Path(tempfile.gettempdir()) / "robocram-workcells"


def _table_urdf(height: float, width: float, ahead: float, depth: float = TABLE_DEPTH) -> Path:
    """A URDF of one box ``height`` [m] high, its centre ``ahead`` [m] along x of its link
    frame, which lies :data:`FRAME_BELOW_TOP` under its top, where the items are: plans
    look at a place's frame to see what is on it, and a wrist camera close over a small
    arm's table sees only a patch round the point it looks at; one file per size."""
    size = f"{depth:.4f} {width:.4f} {height:.4f}"
    centre = f"{ahead:.4f} 0 {FRAME_BELOW_TOP - height / 2:.4f}"
    shape = f'<origin xyz="{centre}"/><geometry><box size="{size}"/></geometry>'
    text = (
        f'<?xml version="1.0"?>\n<robot name="{WORKCELL}"><link name="{TABLE_TOP}">'
        f"<visual>{shape}</visual><collision>{shape}</collision></link></robot>\n"
    )
    URDF_FOLDER.mkdir(parents=True, exist_ok=True)
    sized = f"{height * 1000:.0f}_{width * 1000:.0f}_{ahead * 1000:.0f}"
    sized += "" if depth == TABLE_DEPTH else f"_{depth * 1000:.0f}"
    path = URDF_FOLDER / f"table_{sized}mm.urdf"
    if not path.is_file() or path.read_text("utf-8") != text:
        written = path.with_suffix(f".{os.getpid()}.tmp")  # another process may read it
        written.write_text(text, "utf-8")
        written.replace(path)
    return path


def workcell_scene(robot: str | RobotDescription, world: World | None = None) -> EnvironmentScene:
    """Floor, ``robot`` at the origin (on a pedestal if its arm is low), a table in front
    of it where the tabletop scene puts one, the mug on it where that scene puts it (its
    handle to the left, or facing the arm as there: ``handle_turn.py``) and the bowl to its
    right; the table's top is the KB's
    ``supporting_surface`` and the items' usual place, its frame between the two (where
    a search looks). The delivery spots are :func:`workcell_spots`. Where the mug lies on
    the robot's own top, the table is a plate a hair over it (:data:`PLATE_HAIR`).

    Raises:
        UnfitRobotError: the robot has no gripper arm, or it cannot reach past its base,
            or a link of it stands on its own top where the plate would lie.
    """
    world = world if world is not None else World()
    name, place = robot_at_a_table(world, robot)
    height, (mug_x, mug_y) = place.table_height, place.mug_xy
    height += PLATE_HAIR + PLATE_THICKNESS if place.on_robot else 0.0
    table_x = mug_x - MUG_INSET + TABLE_DEPTH / 2
    side = max(SPREAD * mug_x, MIN_SPREAD)
    width = max(TABLE_WIDTH, 2 * (abs(mug_y) + side + 0.2))
    bowl_x = _aside_x(world, name, (mug_x, mug_y - side, height))
    if place.on_robot:  # a plate over the robot's own top, just round the items' spots
        urdf = _table_urdf(
            PLATE_THICKNESS, 3 * side + 2 * PLATE_MARGIN, 0.0, _plate_depth(mug_x, bowl_x)
        )
    else:
        urdf = _table_urdf(height, width, table_x - (mug_x + bowl_x) / 2)
    environment = EnvironmentDescription(WORKCELL, urdf, (SurfaceDescription(TABLE_TOP, height),))
    middle = Pose(((mug_x + bowl_x) / 2, mug_y - side / 2, height - FRAME_BELOW_TOP))
    world.add_urdf(WORKCELL, environment.urdf, middle, type="environment")
    if place.on_robot:
        _refuse_touching(world, name)
    world.kb.consult(environment.facts(WORKCELL), group=f"{WORKCELL}_semantics")
    items = (
        ItemPlace("mug-1", "mug", TABLE_TOP, ((mug_x - bowl_x) / 2, side / 2)),
        ItemPlace("bowl-1", "bowl", TABLE_TOP, ((bowl_x - mug_x) / 2, -side / 2)),
    )
    objects = {p.name: place_item(world, WORKCELL, p) for p in items}
    turn_handle_to_arm(world, name, objects["mug-1"])
    world.kb.consult(
        usual_location_facts(environment, items, WORKCELL), group=f"{WORKCELL}_contents"
    )
    return EnvironmentScene(world, name, WORKCELL, objects)


def _plate_depth(mug_x: float, bowl_x: float) -> float:
    """The depth [m] of the plate on a robot's own top: the mug's and the bowl's spots
    (as far out as they lie) with :data:`PLATE_MARGIN` round them."""
    return abs(mug_x - bowl_x) + 2 * PLATE_MARGIN


def _refuse_touching(world: World, robot: str) -> None:
    """Raise if the plate laid on ``robot``'s own top touches the robot (a link standing
    on its top where the items' spots are): the plans would take it for a collision."""
    near = world.contacts.link_distances(WORKCELL, distance=0.0)
    touching = sorted({link for _, other, link, _ in near if other.name == robot})
    if touching:
        raise UnfitRobotError(
            robot,
            f"its own top is its workcell's table, but its {', '.join(touching)} stand(s) "
            "where the plate carrying the items' spots lies: give it a clear top under "
            "where its camera looks",
        )


def _aside_x(world: World, robot: str, spot: Vector3) -> float:
    """The x [m, map] of an item's ``spot`` aside of the mug (as far out as it, on the
    table's top): as far out, or nearer where the hand grasping it there lies beyond
    :data:`ASIDE_SHARE` of the arm's reach past the rise at its shoulder (the SO-100's,
    0.10 m over its pan): then on the arc the mug's wrist lies on
    (:func:`~robocram.scenes.placement.grasp_in_reach_x`); never farther out than the mug."""
    arm = placement_arm(world.robot(robot).description)
    if arm is None:
        return spot[0]
    return min(spot[0], grasp_in_reach_x(world, robot, arm, spot, ASIDE_SHARE))


def workcell_spots(scene: EnvironmentScene) -> dict[str, PoseStamped]:
    """Where the items of a workcell scene go (map), each as far ahead as it lies and its
    frame as high as it rests now: the mug as far to its left as the bowl lies to its
    right (nearer, on the arc the hand reaches, where that lies beyond it: :func:`_aside_x`),
    then the bowl where the mug stood. Both spots are in reach if the items are: the
    tabletop pick-up's mug spot, and a step aside as far as the bowl lies."""
    mug = scene.world.pose(scene.items["mug-1"]).position
    bowl = scene.world.pose(scene.items["bowl-1"]).position
    top = scene.world.pose(scene.environment).position[2] + FRAME_BELOW_TOP
    left_y = 2 * mug[1] - bowl[1]
    left = (_aside_x(scene.world, scene.robot, (mug[0], left_y, top)), left_y, mug[2])
    return {
        "mug-1": PoseStamped("map", left),
        "bowl-1": PoseStamped("map", (mug[0], mug[1], bowl[2])),
    }

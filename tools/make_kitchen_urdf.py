"""Write robocram's kitchen: src/robocram/scenes/data/kitchen.urdf.

The facts it also builds are what it means the kitchen to hold; the scene drafts its own
from the URDF (``robocram.scenes.draft_environment``) and a test checks they agree.

A 6 x 5 m room of simple shapes: walls, a counter run along the north wall (cupboard, sink
cabinet, drawer units, stove unit), a fridge, wall cupboards, a second counter run of
drawer units and a cupboard along the east wall, and a dining table. Every drawer is a
prismatic joint and every door a revolute one, each with a handle link of its own, so
plans can grasp the handle and follow the joint. The facts file says which links are
supporting surfaces and which are containers (with their joint and handle), so plans ask
the knowledge base and never hard-code a link name. Run ``python tools/make_kitchen_urdf.py``.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path

from urdf_shapes import Limit, Shape, UrdfBuilder, Vec3, box

PI = math.pi
DATA = Path(__file__).resolve().parents[1] / "src/robocram/scenes/data"
ROOM = (6.0, 5.0)  # [m] inner extents along x and y, centred on the origin
WALL = (0.1, 2.0)  # [m] thickness, height
BASE_HEIGHT = 0.81  # [m] base units, below the counter top
TOP_THICKNESS = 0.04  # [m] counter tops: their surface is at 0.85 m
PLINTH = 0.1  # [m] the solid floor of every unit
DEPTH = 0.6  # [m] base units
WIDTH = 0.6  # [m] every unit
DRAWER_TRAVEL = 0.45  # [m]
DOOR_SWING = 1.6  # [rad]
OPENED = {"drawer": 0.4, "door": 1.4}  # [m | rad] the joint goal that opens a container
NORTH_FRONT = ROOM[1] / 2 - DEPTH  # [m] y of the north run's fronts
EAST_FRONT = ROOM[0] / 2 - DEPTH  # [m] x of the east run's fronts
FACING_SOUTH = -PI / 2  # unit yaw: its front (+x) faces -y
FACING_WEST = PI  # unit yaw: its front faces -x
COMMENT = """
  robocram's kitchen, written by tools/make_kitchen_urdf.py (do not edit).
  Every unit's frame sits on the floor at the middle of its front, x pointing out of the
  front into the room. Drawers slide along +x (prismatic, 0 = closed); doors swing out
  about the vertical hinge on the unit's -y edge (revolute, 0 = closed). Each drawer and
  door has a handle link whose x axis points out of the front.
"""


@dataclass(frozen=True)
class Unit:
    """A cabinet: ``drawers`` stacked drawers, or a door if 0; where and facing which way."""

    name: str
    xyz: Vec3
    yaw: float  # [rad]
    drawers: int = 0
    depth: float = DEPTH
    height: float = BASE_HEIGHT
    closed_top: bool = False
    shelves: tuple[float, ...] = ()  # [m] heights of inner shelves above the unit's floor


NORTH = (
    Unit("cupboard", (-2.6, NORTH_FRONT, 0.0), FACING_SOUTH, shelves=(0.45,)),
    Unit("sink_cabinet", (-2.0, NORTH_FRONT, 0.0), FACING_SOUTH),
    Unit("drawer_unit", (-1.4, NORTH_FRONT, 0.0), FACING_SOUTH, drawers=3),
    Unit("stove_unit", (-0.8, NORTH_FRONT, 0.0), FACING_SOUTH, drawers=2),
    Unit("cutlery_unit", (-0.2, NORTH_FRONT, 0.0), FACING_SOUTH, drawers=4),
)
FRIDGE = Unit(
    "fridge",
    (0.55, ROOM[1] / 2 - 0.65, 0.0),
    FACING_SOUTH,
    depth=0.65,
    height=1.8,
    closed_top=True,
    shelves=(0.55, 1.05),
)
WALL_CUPBOARDS = tuple(
    Unit(
        f"wall_cupboard_{i + 1}",
        (u.xyz[0], ROOM[1] / 2 - 0.35, 1.4),
        FACING_SOUTH,
        depth=0.35,
        height=0.6,
        closed_top=True,
        shelves=(0.3,),
    )
    for i, u in enumerate(NORTH)
)
EAST = (
    Unit("east_drawers_1", (EAST_FRONT, 1.5, 0.0), FACING_WEST, drawers=3),
    Unit("east_drawers_2", (EAST_FRONT, 0.9, 0.0), FACING_WEST, drawers=3),
    Unit("east_drawers_3", (EAST_FRONT, 0.3, 0.0), FACING_WEST, drawers=3),
    Unit("east_cupboard", (EAST_FRONT, -0.3, 0.0), FACING_WEST, shelves=(0.45,)),
)
FACING_EAST = 0.0  # unit yaw: its front faces +x
WEST_FRONT = -ROOM[0] / 2 + DEPTH  # [m] x of the west run's fronts (the big kitchen's)
WEST = tuple(
    Unit(f"west_drawers_{i + 1}", (WEST_FRONT, 1.2 - 0.6 * i, 0.0), FACING_EAST, drawers=4)
    for i in range(5)
)  # the big kitchen's: a counter run of drawer units along the west wall
WEST_CUPBOARDS = tuple(
    Unit(
        f"west_cupboard_{i + 1}",
        (-ROOM[0] / 2 + 0.35, u.xyz[1], 1.4),
        FACING_EAST,
        depth=0.35,
        height=0.6,
        closed_top=True,
        shelves=(0.2, 0.4),
    )
    for i, u in enumerate(WEST)
)
BIG = Path(__file__).resolve().parents[1] / "tests/data/big_kitchen"
TABLE = ((0.0, -1.4), (1.4, 0.9), 0.75)  # centre [m], top extents [m], top height [m]


class Facts:
    """The semantic facts collected while the links are written."""

    def __init__(self) -> None:
        self.surfaces: list[str] = []
        self.containers: list[tuple[str, str, str, str]] = []  # link, joint, handle, kind
        self.fronts: dict[str, float] = {}  # container link -> its unit's yaw [rad]

    def text(self) -> str:
        """The Prolog fact group: supporting surfaces and containers of the kitchen."""
        lines = [
            "% robocram's kitchen: written by tools/make_kitchen_urdf.py (do not edit).",
            "% supporting_surface(Env, Link): Link's top is a place to put things on.",
            *(f"supporting_surface(kitchen, {s})." for s in self.surfaces),
            "% container(Env, Link, Joint, Handle): things lie in Link; moving Joint opens it,",
            "% pulling Handle moves Joint.",
            *(f"container(kitchen, {c}, {j}, {h})." for c, j, h, _ in self.containers),
            "% container_kind(Env, Link, Kind): drawer (prismatic) or door (revolute).",
            *(f"container_kind(kitchen, {c}, {k})." for c, _, _, k in self.containers),
            "% container_opening(Env, Link, Goal): the joint value [m | rad] that opens it.",
            *(f"container_opening(kitchen, {c}, {OPENED[k]})." for c, _, _, k in self.containers),
            "% container_front(Env, Link, Yaw): the way [rad] out of its front (its unit's +x).",
            *(f"container_front(kitchen, {c}, {round(y, 4)!r})." for c, y in self.fronts.items()),
        ]
        return "\n".join(lines) + "\n"


def handle(b: UrdfBuilder, parent: str, name: str, xyz: Vec3, upright: bool) -> None:
    """A bar handle on two standoffs, 4 cm out of ``parent``'s front; x points out."""
    bar = box(0.02, 0.02, 0.14) if upright else box(0.02, 0.14, 0.02)
    offsets = ((0, 0, 0.055), (0, 0, -0.055)) if upright else ((0, 0.055, 0), (0, -0.055, 0))
    stands = tuple(box(0.03, 0.015, 0.015, (-0.025, dy, dz)) for _, dy, dz in offsets)
    b.joint(f"{name}_joint", "fixed", parent, name, xyz)
    b.link(name, (bar, *stands), mass=0.1, color="grey")


def carcass(u: Unit) -> tuple[Shape, ...]:
    """Floor, sides and back (and a top, shelves) of a unit; its front stays open."""
    d, w, h = u.depth, WIDTH, u.height
    shapes = [
        box(d, w, PLINTH, (-d / 2, 0, PLINTH / 2)),
        box(d, 0.02, h, (-d / 2, w / 2 - 0.01, h / 2)),
        box(d, 0.02, h, (-d / 2, -w / 2 + 0.01, h / 2)),
        box(0.02, w, h, (-d + 0.01, 0, h / 2)),
    ]
    if u.closed_top:
        shapes.append(box(d, w, 0.02, (-d / 2, 0, h - 0.01)))
    shapes += [box(d - 0.04, w - 0.04, 0.02, (-d / 2 - 0.01, 0, z)) for z in u.shelves]
    return tuple(shapes)


def drawer(b: UrdfBuilder, u: Unit, k: int, facts: Facts) -> None:
    """Drawer ``k`` (0 at the bottom) of unit ``u``: front, floor, sides and back."""
    slot = (u.height - PLINTH) / u.drawers
    name = f"{u.name}_drawer_{k + 1}"
    inner_w, inner_d, wall = WIDTH - 0.06, u.depth - 0.08, min(0.15, slot - 0.05)
    body = -0.02 - inner_d / 2  # [m] x of the body's centre behind the front
    b.joint(
        f"{name}_joint",
        "prismatic",
        f"{u.name}_body",
        name,
        (0.0, 0.0, PLINTH + k * slot),
        axis=(1.0, 0.0, 0.0),
        limit=Limit(0.0, DRAWER_TRAVEL, 0.5, 100.0),
    )
    shapes = (
        box(0.02, WIDTH - 0.01, slot - 0.01, (-0.01, 0, slot / 2)),
        box(inner_d, inner_w, 0.01, (body, 0, 0.015)),
        box(inner_d, 0.01, wall, (body, inner_w / 2 - 0.005, 0.01 + wall / 2)),
        box(inner_d, 0.01, wall, (body, -inner_w / 2 + 0.005, 0.01 + wall / 2)),
        box(0.01, inner_w, wall, (-0.02 - inner_d + 0.005, 0, 0.01 + wall / 2)),
    )
    b.link(name, shapes, mass=2.0, color="white")
    handle(b, name, f"{name}_handle", (0.04, 0.0, slot - 0.06), upright=False)
    facts.containers.append((name, f"{name}_joint", f"{name}_handle", "drawer"))
    facts.fronts[name] = u.yaw


def door(b: UrdfBuilder, u: Unit, facts: Facts) -> None:
    """The door of unit ``u``, hinged on its -y edge, swinging out; handle by the far edge."""
    name = f"{u.name}_door"
    top = u.height - (0.01 if u.closed_top else 0.0)
    bottom = PLINTH if u.xyz[2] == 0.0 else 0.0
    tall = top - bottom
    b.joint(
        f"{name}_joint",
        "revolute",
        f"{u.name}_body",
        name,
        (0.01, -WIDTH / 2, bottom),
        axis=(0.0, 0.0, -1.0),
        limit=Limit(0.0, DOOR_SWING, 1.0, 100.0),
    )
    b.link(name, (box(0.02, WIDTH - 0.01, tall, (0, WIDTH / 2, tall / 2)),), 3.0, "white")
    grip_z = 0.12 if u.xyz[2] > 0.0 else min(tall - 0.12, 1.0)
    handle(b, name, f"{name}_handle", (0.04, WIDTH - 0.06, grip_z), upright=True)
    facts.containers.append((f"{u.name}_body", f"{name}_joint", f"{name}_handle", "door"))
    facts.fronts[f"{u.name}_body"] = u.yaw


def unit(b: UrdfBuilder, u: Unit, facts: Facts) -> None:
    """A unit fixed to the room, with its drawers or its door."""
    b.joint(f"{u.name}_joint", "fixed", "kitchen_root", f"{u.name}_body", u.xyz, (0, 0, u.yaw))
    b.link(f"{u.name}_body", carcass(u), color="white")
    if u.drawers:
        for k in range(u.drawers):
            drawer(b, u, k, facts)
    else:
        door(b, u, facts)


def slab(b: UrdfBuilder, name: str, centre: Vec3, size: Vec3, color: str, facts: Facts) -> None:
    """A horizontal top (a counter top, the sink, the stove) fixed to the room: a surface."""
    b.joint(f"{name}_joint", "fixed", "kitchen_root", name, centre)
    b.link(name, (box(*size),), color=color)
    facts.surfaces.append(name)


def counters(b: UrdfBuilder, facts: Facts) -> None:
    """Counter tops over both runs, with a sink block and a stove block on the north one."""
    z = BASE_HEIGHT + TOP_THICKNESS / 2
    north_x = (NORTH[0].xyz[0] - WIDTH / 2, NORTH[-1].xyz[0] + WIDTH / 2)
    north_depth = DEPTH + 0.02
    north_y = ROOM[1] / 2 - north_depth / 2
    size = (north_x[1] - north_x[0], north_depth, TOP_THICKNESS)
    slab(b, "counter_top_north", ((north_x[0] + north_x[1]) / 2, north_y, z), size, "grey", facts)
    east_y = (EAST[-1].xyz[1] - WIDTH / 2, EAST[0].xyz[1] + WIDTH / 2)
    east_x = ROOM[0] / 2 - north_depth / 2
    size = (north_depth, east_y[1] - east_y[0], TOP_THICKNESS)
    slab(b, "counter_top_east", (east_x, (east_y[0] + east_y[1]) / 2, z), size, "grey", facts)
    top = BASE_HEIGHT + TOP_THICKNESS
    slab(b, "sink", (NORTH[1].xyz[0], north_y, top + 0.01), (0.45, 0.4, 0.02), "blue", facts)
    slab(b, "stove", (NORTH[3].xyz[0], north_y, top + 0.01), (0.55, 0.5, 0.02), "dark", facts)


def walls(b: UrdfBuilder) -> None:
    """Four walls around the room, their inner faces on its edges; a link each, so each
    one's bounds are its own (one link's bounds would cover the whole room)."""
    (x, y), (t, h) = ROOM, WALL
    shapes = {
        "wall_north": box(x + 2 * t, t, h, (0, y / 2 + t / 2, h / 2)),
        "wall_south": box(x + 2 * t, t, h, (0, -y / 2 - t / 2, h / 2)),
        "wall_east": box(t, y, h, (x / 2 + t / 2, 0, h / 2)),
        "wall_west": box(t, y, h, (-x / 2 - t / 2, 0, h / 2)),
    }
    for name, shape in shapes.items():
        b.joint(f"{name}_joint", "fixed", "kitchen_root", name)
        b.link(name, (shape,), color="white")


def table(b: UrdfBuilder, facts: Facts) -> None:
    """The dining table: its top is a surface; four legs."""
    (cx, cy), (sx, sy), height = TABLE
    b.joint("table_joint", "fixed", "kitchen_root", "table_top", (cx, cy, height - 0.02))
    legs = tuple(
        box(0.05, 0.05, height - 0.04, (dx * (sx / 2 - 0.06), dy * (sy / 2 - 0.06), -height / 2))
        for dx in (-1, 1)
        for dy in (-1, 1)
    )
    b.link("table_top", (box(sx, sy, 0.04), *legs), color="orange")
    facts.surfaces.append("table_top")


def west_counter(b: UrdfBuilder, facts: Facts) -> None:
    """The big kitchen's counter top over its west run."""
    depth = DEPTH + 0.02
    ys = (WEST[-1].xyz[1] - WIDTH / 2, WEST[0].xyz[1] + WIDTH / 2)
    size = (depth, ys[1] - ys[0], TOP_THICKNESS)
    centre = (-ROOM[0] / 2 + depth / 2, (ys[0] + ys[1]) / 2, BASE_HEIGHT + TOP_THICKNESS / 2)
    slab(b, "counter_top_west", centre, size, "grey", facts)


def build(big: bool = False) -> tuple[str, str]:
    """The kitchen URDF and its fact group; ``big``: with a west run of five drawer
    units and five wall cupboards over it (139 links, more than one PyBullet body holds)."""
    b = UrdfBuilder("big_kitchen" if big else "kitchen", COMMENT)
    facts = Facts()
    b.link("kitchen_root")
    walls(b)
    extra = (*WEST, *WEST_CUPBOARDS) if big else ()
    for u in (*NORTH, FRIDGE, *WALL_CUPBOARDS, *EAST, *extra):
        unit(b, u, facts)
    counters(b, facts)
    if big:
        west_counter(b, facts)
    table(b, facts)
    return b.xml(), facts.text()


def main() -> None:
    """Write the URDF next to the scenes package (``--big``: the big kitchen, as test data)."""
    big = "--big" in sys.argv[1:]
    urdf, _ = build(big)
    folder, name = (BIG, "big_kitchen.urdf") if big else (DATA, "kitchen.urdf")
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_text(urdf, encoding="utf-8")
    print(f"wrote {folder / name}")


if __name__ == "__main__":
    main()

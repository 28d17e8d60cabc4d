"""The breakfast kitchen: robocram's kitchen holding what a breakfast for two is made of.

The same kitchen as :func:`kitchen_scene` (its URDF, its drafted facts), stocked as a
household keeps things: bowls in the top drawer of the drawer unit, cups in the cutlery
unit's top drawer, the spoons and the knife in the one below, the milk on the fridge's upper
shelf, the cereal on the east counter, the bread and the sponge on the north counter.
Each item type's usual place is a ``usual_location/3`` fact (group ``kitchen_semantics``),
so a plan reads it and a user changes it with one fact (``kb.consult(..., group=...)``).
The seats at the table are facts too (:data:`SEATS`, group ``kitchen_seats``), and so are
the spots in those places where each type is put back (``usual_spot/5``, group
``kitchen_spots``: clearing puts a bowl back where bowls are kept, not anywhere in the drawer).

A separate builder, so the plain kitchen scene and every result on it stay as they were.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import replace
from functools import cache

from robocram.logic import name_atom
from robocram.robots import RobotDescription
from robocram.scenes.environment_description import EnvironmentDescription
from robocram.scenes.environment_scene import EnvironmentScene, ItemPlace, environment_scene
from robocram.scenes.kitchen_scene import KITCHEN, ROBOT_START, kitchen_description
from robocram.world import World

FRIDGE_UPPER_SHELF = 1.3  # [m] over the fridge's floor: items go on the first shelf below

# Unit frames have x out of the front, so negative x is inside a drawer or behind an edge.
BREAKFAST_PLACES = (
    ItemPlace("bowl-1", "bowl", "drawer_unit_drawer_3", (-0.26, 0.12)),
    ItemPlace("bowl-2", "bowl", "drawer_unit_drawer_3", (-0.26, -0.12)),
    ItemPlace("cup-1", "cup", "cutlery_unit_drawer_4", (-0.24, 0.18)),
    ItemPlace("cup-2", "cup", "cutlery_unit_drawer_4", (-0.24, -0.18)),
    ItemPlace("spoon-1", "spoon", "cutlery_unit_drawer_3", (-0.24, 0.09)),  # 16 cm along y
    ItemPlace("spoon-2", "spoon", "cutlery_unit_drawer_3", (-0.24, -0.09)),
    ItemPlace("knife-1", "knife", "cutlery_unit_drawer_3", (-0.1, 0.0)),
    ItemPlace("milk-1", "milk", "fridge_body", (-0.2, 0.05), below=FRIDGE_UPPER_SHELF),
    # on the counter beside the stove and the sink, not on them (their 2 cm slabs)
    ItemPlace("cereal-1", "cereal_box", "counter_top_north", (0.2, -0.1)),
    ItemPlace("bread-1", "bread", "counter_top_north", (1.05, -0.05)),
    ItemPlace("sponge-1", "sponge", "counter_top_north", (-0.9, -0.15)),
)

# seat(Env, Surface, Seat, X, Y, Yaw): where a person sits at a table, in the table top's
# frame [m], and the way [rad] they face (into the table). The kitchen's table is 1.4 m
# along x and 0.9 m along y; people sit along its long sides, the north side first.
SEATS = (
    ("table_top", 1, -0.35, 0.45, -1.5707963267948966),
    ("table_top", 2, 0.35, 0.45, -1.5707963267948966),
    ("table_top", 3, -0.35, -0.45, 1.5707963267948966),
    ("table_top", 4, 0.35, -0.45, 1.5707963267948966),
)


def seat_facts(environment: str, seats: Iterable[tuple[str, int, float, float, float]]) -> str:
    """``seat/6`` facts (Prolog text) of ``environment``'s seats."""
    env = name_atom(environment)
    return "".join(
        f"seat({env}, {name_atom(link)}, {n}, {x!r}, {y!r}, {yaw!r}).\n"
        for link, n, x, y, yaw in seats
    )


def usual_spot_facts(environment: str, places: Iterable[ItemPlace]) -> str:
    """``usual_spot/5`` facts (Prolog text): each place's spot, in its link's frame [m]."""
    env = name_atom(environment)
    return "".join(
        f"usual_spot({name_atom(p.kind)}, {env}, {name_atom(p.link)}, {p.xy[0]!r}, {p.xy[1]!r}).\n"
        for p in places
    )


@cache
def breakfast_description(kept: tuple[ItemPlace, ...] = BREAKFAST_PLACES) -> EnvironmentDescription:
    """The kitchen's description with the breakfast items' usual places (where ``kept``
    keeps them: a household's own arrangement)."""
    usual = tuple(sorted({(p.kind, p.link) for p in kept}))
    return replace(kitchen_description(), usual_locations=usual)


def breakfast_scene(
    robot: str | RobotDescription,
    world: World | None = None,
    places: Iterable[ItemPlace] | None = None,
    kept: Sequence[ItemPlace] = BREAKFAST_PLACES,
) -> EnvironmentScene:
    """The kitchen with the breakfast items in ``places`` (default: where they are kept),
    ``robot`` (arms parked) in the middle, and the table's seats as facts.

    ``kept`` is the household's arrangement, which the knowledge holds: each kind's usual
    place and each item's spot in it (``usual_spot/5``), where clearing brings it back.
    Items moved from where they are kept (``places``: a seeded variant) leave those facts
    as they are: a plan finds them by looking.
    """
    kept = tuple(kept)
    scene = environment_scene(
        breakfast_description(kept), robot, kept if places is None else places, ROBOT_START,
        world,
    )  # fmt: skip
    scene.world.kb.consult(seat_facts(KITCHEN, SEATS), group=f"{KITCHEN}_seats")
    scene.world.kb.consult(usual_spot_facts(KITCHEN, kept), group=f"{KITCHEN}_spots")
    return scene

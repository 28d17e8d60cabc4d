"""Where each thing of a set table goes: place settings at the seats, shared things between.

A seat is a fact of the table (``seat(Env, Link, Seat, X, Y, Yaw)``: where a person sits,
in the table link's frame, facing into the table). A place setting is a list of
:class:`Setting` rows in the seat's frame (x into the table from its edge, y to the
person's left): the standard one puts the bowl 0.2 m in front of the person, the spoon to
its right and the cup beyond the spoon, as far apart as the ``on`` location keeps things
(its 3 cm margin round each thing's footprint circle). Shared things (milk, cereal)
stand on the table's middle line, spread evenly. Every spot is a map pose at the table
link's height; the height the object rests at comes from the ``on`` location.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from robocram.knowledge.scene_predicates import SEAT
from robocram.logic import current_kb
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.errors import PlanSetupError
from robocram.tf import Pose
from robocram.tf import quaternion as quat

SHARED_SPACING = 0.2  # [m] between shared things on the table's middle line
TOLERANCE = 0.05  # [m] how far a set thing may stand from its spot


@dataclass(frozen=True)
class Setting:
    """One thing of a place setting: its type, ``forward`` [m] from the table's edge at the
    seat into the table and ``right`` [m] of the seat's middle, as the person sees it."""

    type: str
    forward: float
    right: float


STANDARD_SETTING = (
    Setting("bowl", 0.2, 0.0),
    Setting("spoon", 0.2, 0.21),
    Setting("cup", 0.4, 0.21),
)
SHARED = ("milk",)


@dataclass(frozen=True)
class Spot:
    """Where one thing of the set table goes: its type, the seat (0: shared), the map pose."""

    type: str
    seat: int
    pose: Pose  # [m] map, at the table link's height


@dataclass(frozen=True)
class Table:
    """A table: the environment and link the seats are facts of."""

    environment: str
    link: str


def table_with_seats(table: Table | tuple[str, str] | None) -> Table:
    """``table``, or the first table the KB gives seats for."""
    if table is not None:
        return table if isinstance(table, Table) else Table(*table)
    row = SEAT.first(current_kb())
    if row is None:
        raise PlanSetupError(
            "the KB knows no seat/6 facts, so no table to set; load a scene with seats "
            "(robocram.scenes.breakfast_scene) or give table=(environment, link)"
        )
    return Table(row.environment, row.link)


def spots(
    table: Table, people: int, setting: Sequence[Setting], shared: Sequence[str]
) -> list[Spot]:
    """The spots of ``people`` place settings, seats in the KB's order, and of ``shared``.

    Raises:
        PlanSetupError: fewer seats at the table than people, or no people.
    """
    seats = sorted(
        SEAT.answers(current_kb(), environment=table.environment, link=table.link),
        key=lambda row: row.seat,
    )
    if not 1 <= people <= len(seats):
        raise PlanSetupError(
            f"{table.link!r} of {table.environment!r} seats {len(seats)}, asked to set it for "
            f"{people}; give 1 to {len(seats)} people or add seat/6 facts"
        )
    origin = environment_link_pose(table.environment, table.link, "a table")
    found = []
    for row in seats[:people]:
        seat = origin * Pose((row.x, row.y, 0.0), quat.from_euler(0.0, 0.0, row.yaw))
        for item in setting:
            found.append(
                Spot(item.type, row.seat, _flat(seat * Pose((item.forward, -item.right, 0.0))))
            )
    middle = (len(shared) - 1) / 2
    for i, kind in enumerate(shared):
        found.append(Spot(kind, 0, _flat(origin * Pose(((i - middle) * SHARED_SPACING, 0.0, 0.0)))))
    return found


def _flat(pose: Pose) -> Pose:
    """``pose`` turned upright: only its heading kept."""
    yaw = quat.to_euler(pose.orientation)[2]
    return Pose(pose.position, quat.from_euler(0.0, 0.0, yaw))


def distance_on_table(spot: Pose, position: tuple[float, float, float]) -> float:
    """How far [m] ``position`` lies from ``spot`` over the table (horizontally)."""
    return math.hypot(position[0] - spot.position[0], position[1] - spot.position[1])

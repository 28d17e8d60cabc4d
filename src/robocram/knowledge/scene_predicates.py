"""Facts a scene provides about its environment: containers, surfaces, usual places and
spots, seats.

``tools/make_kitchen_urdf.py`` writes them for robocram's kitchen (``kitchen.pl``);
plans ask these and never name a link.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.knowledge.argument import unit
from robocram.knowledge.predicate import Predicate, Source


@dataclass(frozen=True)
class ContainerFact:
    """A container link of an environment, the joint that opens it and its handle."""

    environment: str
    link: str
    joint: str
    handle: str


@dataclass(frozen=True)
class ContainerKind:
    """Whether a container is a ``drawer`` or a ``door``."""

    environment: str
    link: str
    kind: str


@dataclass(frozen=True)
class ContainerOpening:
    """The joint value that opens a container fully."""

    environment: str
    link: str
    opened: float = unit("m | rad")


@dataclass(frozen=True)
class ContainerFront:
    """The yaw, in the environment's frame, of the way out of a container's front.

    The robot stands on that side to open it; a handle's own frame need not point there.
    """

    environment: str
    link: str
    front: float = unit("rad")


@dataclass(frozen=True)
class UsualLocation:
    """Where objects of a type usually are."""

    type: str
    environment: str
    link: str


@dataclass(frozen=True)
class UsualSpot:
    """A spot, in a usual place's link frame, where a thing of a type is put back."""

    type: str
    environment: str
    link: str
    x: float = unit("m")
    y: float = unit("m")


@dataclass(frozen=True)
class Seat:
    """Where person ``seat`` sits at a table, in the table's link frame, facing into it."""

    environment: str
    link: str
    seat: int
    x: float = unit("m")
    y: float = unit("m")
    yaw: float = unit("rad")


@dataclass(frozen=True)
class SupportingSurface:
    """A link of an environment things can stand on."""

    environment: str
    link: str


_S = Source.SCENE
CONTAINER = Predicate("container", ContainerFact, _S, "a drawer or door, its joint and handle")
CONTAINER_KIND = Predicate("container_kind", ContainerKind, _S, "a container's kind")
CONTAINER_OPENING = Predicate(
    "container_opening", ContainerOpening, _S, "how far a container opens"
)
CONTAINER_FRONT = Predicate(
    "container_front", ContainerFront, _S, "which way a container's front faces"
)
USUAL_LOCATION = Predicate("usual_location", UsualLocation, _S, "where a type of object is kept")
SUPPORTING_SURFACE = Predicate(
    "supporting_surface", SupportingSurface, _S, "a surface objects can stand on"
)
USUAL_SPOT = Predicate("usual_spot", UsualSpot, _S, "a spot in a usual place for a type")
SEAT = Predicate("seat", Seat, _S, "where a person sits at a table")

SCENE_PREDICATES: tuple[Predicate[Any], ...] = (
    CONTAINER,
    CONTAINER_KIND,
    CONTAINER_OPENING,
    CONTAINER_FRONT,
    USUAL_LOCATION,
    USUAL_SPOT,
    SUPPORTING_SURFACE,
    SEAT,
)

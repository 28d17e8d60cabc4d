"""The world as predicates: computed by the world of a knowledge base on every call.

Every predicate takes the world first (``W``, bound by ``world(W)``; a typed query binds
it itself); objects, robots, links and joints are name atoms, and unbound names
enumerate. Predicates that change the world (``set_joint_state``, ``set_object_pose``,
``attach``, ``detach``, ``simulate``, ``settle``) succeed once.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.knowledge.argument import Names, unit
from robocram.knowledge.predicate import Predicate, Source
from robocram.tf import Pose


@dataclass(frozen=True)
class TheWorld:
    """The world itself."""

    world: object


@dataclass(frozen=True)
class WorldObject:
    """An object (robots too) of the world."""

    world: object
    object: str


@dataclass(frozen=True)
class WorldRobot:
    """A robot of the world."""

    world: object
    robot: str


@dataclass(frozen=True)
class ObjectType:
    """An object's type (``mug``)."""

    world: object
    object: str
    type: str


@dataclass(frozen=True)
class ObjectPose:
    """An object's pose in ``map``."""

    world: object
    object: str
    pose: Pose = unit("m, map")


@dataclass(frozen=True)
class SimulatedTime:
    """A span of simulated time."""

    world: object
    seconds: float = unit("s")


@dataclass(frozen=True)
class SettlingTime:
    """At most a span of simulated time for an object to come to rest."""

    world: object
    object: str
    seconds: float = unit("s")


@dataclass(frozen=True)
class JointState:
    """A joint's value."""

    world: object
    robot: str
    joint: str
    value: float = unit("rad | m")


@dataclass(frozen=True)
class LinkPose:
    """A link's pose in ``map``."""

    world: object
    object: str
    link: str
    pose: Pose = unit("m, map")


@dataclass(frozen=True)
class Attached:
    """An object carried by a link of a robot (or of any object)."""

    world: object
    robot: str
    link: str
    object: str


@dataclass(frozen=True)
class Attachment:
    """An object to attach to a link."""

    world: object
    object: str
    robot: str
    link: str


@dataclass(frozen=True)
class ObjectPair:
    """Two distinct objects in a spatial relation."""

    world: object
    object: str
    other: str


@dataclass(frozen=True)
class Visible:
    """An object a robot's camera sees."""

    world: object
    robot: str
    object: str


@dataclass(frozen=True)
class Occluders:
    """The objects between a robot's camera and an object."""

    world: object
    robot: str
    object: str
    occluders: Names


_W = Source.WORLD
WORLD = Predicate("world", TheWorld, _W, "the world this knowledge base is of")
OBJECT = Predicate("object", WorldObject, _W, "an object of the world, robots included")
OBJECT_TYPE = Predicate("object_type", ObjectType, _W, "an object's type")
OBJECT_POSE = Predicate("object_pose", ObjectPose, _W, "an object's pose now")
SET_OBJECT_POSE = Predicate("set_object_pose", ObjectPose, _W, "puts an object at a pose")
SIMULATE = Predicate("simulate", SimulatedTime, _W, "runs the physics for a while")
SETTLING = Predicate(
    "settle", SettlingTime, _W, "runs the physics until an object rests (at most Seconds)"
)
ROBOT_IN_WORLD = Predicate("robot", WorldRobot, _W, "a robot of the world")
JOINT_STATE = Predicate("joint_state", JointState, _W, "a robot joint's value now")
SET_JOINT_STATE = Predicate("set_joint_state", JointState, _W, "sets a robot joint's value")
LINK_POSE = Predicate("link_pose", LinkPose, _W, "a link's pose now")
ATTACHED = Predicate("attached", Attached, _W, "an object a link carries")
ATTACH = Predicate("attach", Attachment, _W, "attaches an object to a link")
DETACH = Predicate("detach", WorldObject, _W, "lets an attached object go")
CONTACT = Predicate("contact", ObjectPair, _W, "two objects touch")
SUPPORTED_BY = Predicate("supported_by", ObjectPair, _W, "an object rests on the other")
ABOVE = Predicate("above", ObjectPair, _W, "an object is above the other")
BELOW = Predicate("below", ObjectPair, _W, "an object is below the other")
STABLE_OBJECT = Predicate("stable", WorldObject, _W, "an object stays put under physics")
STABLE_WORLD = Predicate("stable", TheWorld, _W, "every object stays put under physics")
VISIBLE = Predicate("visible", Visible, _W, "a robot's camera sees an object")
OCCLUDING_OBJECTS = Predicate(
    "occluding_objects", Occluders, _W, "what hides an object from a robot's camera"
)

WORLD_PREDICATES: tuple[Predicate[Any], ...] = (
    WORLD,
    OBJECT,
    OBJECT_TYPE,
    OBJECT_POSE,
    SET_OBJECT_POSE,
    SIMULATE,
    SETTLING,
    ROBOT_IN_WORLD,
    JOINT_STATE,
    SET_JOINT_STATE,
    LINK_POSE,
    ATTACHED,
    ATTACH,
    DETACH,
    CONTACT,
    SUPPORTED_BY,
    ABOVE,
    BELOW,
    STABLE_OBJECT,
    STABLE_WORLD,
    VISIBLE,
    OCCLUDING_OBJECTS,
)

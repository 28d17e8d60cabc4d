"""The projection world: PyBullet scenes of objects and robots, reasoning and predicates."""

from robocram.world.attachment import Attachment
from robocram.world.body_spec import MeshSpec, ShapeSpec, UrdfSpec
from robocram.world.camera import Camera
from robocram.world.catalogue import catalogue_names
from robocram.world.collision_shapes import CollisionShape
from robocram.world.contact_point import ContactPoint
from robocram.world.derived import Derived
from robocram.world.errors import (
    AttachmentCycleError,
    BodyLoadError,
    DuplicateObjectError,
    NoCameraError,
    NotARobotError,
    TooManyLinksError,
    UnknownItemError,
    UnknownJointError,
    UnknownLinkError,
    UnknownObjectError,
    WorldClosedError,
    WorldError,
    WorldUsageError,
    WorldValueError,
)
from robocram.world.joint_state import ClampedJoint, JointLimits
from robocram.world.obstacle_boxes import ObstacleBoxes
from robocram.world.planning_area import AREA_MARGIN, PlanningArea
from robocram.world.raw_distances import LinkGap, LinkSlot, RawDistances
from robocram.world.ray_hit import RayHit
from robocram.world.robot_handle import RobotHandle
from robocram.world.versions import BodyStamps, Stamp, Versions, body_stamps, changed_bodies
from robocram.world.visibility import Visibility
from robocram.world.world import World
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_state import WorldState

__all__ = [
    "AREA_MARGIN",
    "Attachment",
    "AttachmentCycleError",
    "BodyStamps",
    "BodyLoadError",
    "Camera",
    "ClampedJoint",
    "CollisionShape",
    "ContactPoint",
    "Derived",
    "DuplicateObjectError",
    "JointLimits",
    "LinkGap",
    "LinkSlot",
    "MeshSpec",
    "NoCameraError",
    "NotARobotError",
    "ObstacleBoxes",
    "PlanningArea",
    "RawDistances",
    "RayHit",
    "RobotHandle",
    "RobotObject",
    "ShapeSpec",
    "Stamp",
    "TooManyLinksError",
    "UnknownItemError",
    "UnknownJointError",
    "UnknownLinkError",
    "UnknownObjectError",
    "UrdfSpec",
    "Versions",
    "Visibility",
    "World",
    "WorldValueError",
    "WorldClosedError",
    "WorldError",
    "WorldObject",
    "WorldState",
    "WorldUsageError",
    "body_stamps",
    "catalogue_names",
    "changed_bodies",
]

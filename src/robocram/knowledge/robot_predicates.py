"""CRAM's robot interface predicates: the facts a robot description provides.

Each robot's facts live in its own fact group ``<name>_description``
(:func:`robocram.robots.install_description`); lists are Prolog lists and joint states
lists of ``[Joint, Value]`` pairs. The neck arm of a robot answers ``arm_joints/3`` and
the like, but not ``arm/2``: plans that pick with "any arm" must not pick with the neck.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.knowledge.argument import JointStates, Names, Vector, unit
from robocram.knowledge.predicate import Need, Predicate, Source
from robocram.tf import Pose


@dataclass(frozen=True)
class Robot:
    """A robot's name."""

    robot: str


@dataclass(frozen=True)
class RobotDescriptionFact:
    """The Python description a robot's facts were made from."""

    robot: str
    description: object


@dataclass(frozen=True)
class RobotFrame:
    """A frame of the robot as a whole."""

    robot: str
    frame: str


@dataclass(frozen=True)
class CameraHeight:
    """How high the camera frame is."""

    robot: str
    height: float = unit("m")


@dataclass(frozen=True)
class CameraAngle:
    """A field of view of the camera."""

    robot: str
    angle: float = unit("rad")


@dataclass(frozen=True)
class Arm:
    """An arm of a robot."""

    robot: str
    arm: str


@dataclass(frozen=True)
class ArmJoints:
    """The joints of an arm, base first."""

    robot: str
    arm: str
    joints: Names


@dataclass(frozen=True)
class ArmLinks:
    """Links of an arm, base first."""

    robot: str
    arm: str
    links: Names


@dataclass(frozen=True)
class ArmLink:
    """One link of an arm."""

    robot: str
    arm: str
    link: str


@dataclass(frozen=True)
class ArmFrame:
    """A frame of an arm."""

    robot: str
    arm: str
    frame: str


@dataclass(frozen=True)
class ArmJoint:
    """One joint of an arm."""

    robot: str
    arm: str
    joint: str


@dataclass(frozen=True)
class GripperOpening:
    """How far an arm's fingers part."""

    robot: str
    arm: str
    opening: float = unit("m")


@dataclass(frozen=True)
class ArmDirection:
    """Which way an arm works, about the base's z: 0 straight ahead, -pi/2 its right."""

    robot: str
    arm: str
    yaw: float = unit("rad")


@dataclass(frozen=True)
class ParkingPose:
    """An arm's parking configuration; empty: the arm stays as it is."""

    robot: str
    arm: str
    joint_states: JointStates = unit("rad | m")


@dataclass(frozen=True)
class CarryingPose:
    """An arm's configuration to carry an object in."""

    robot: str
    arm: str
    joint_states: JointStates = unit("rad | m")


@dataclass(frozen=True)
class JointType:
    """The URDF type of a joint."""

    robot: str
    joint: str
    type: str


@dataclass(frozen=True)
class JointLink:
    """A link a joint connects."""

    robot: str
    joint: str
    link: str


@dataclass(frozen=True)
class JointAxis:
    """A joint's axis in its child frame."""

    robot: str
    joint: str
    axis: Vector


@dataclass(frozen=True)
class JointOrigin:
    """A joint's origin in its parent link's frame."""

    robot: str
    joint: str
    origin: Pose = unit("m")


@dataclass(frozen=True)
class JointLimit:
    """A limit of a joint."""

    robot: str
    joint: str
    limit: float = unit("rad | m")


@dataclass(frozen=True)
class JointMimic:
    """A joint that follows another: value = multiplier * master + offset."""

    robot: str
    joint: str
    master: str
    multiplier: float
    offset: float = unit("rad | m")


@dataclass(frozen=True)
class RobotJoints:
    """Joints of the robot as a whole."""

    robot: str
    joints: Names


@dataclass(frozen=True)
class RobotLinks:
    """Links of the robot as a whole."""

    robot: str
    links: Names


@dataclass(frozen=True)
class NeckParkingPose:
    """The neck's parking configuration."""

    robot: str
    joint_states: JointStates = unit("rad | m")


@dataclass(frozen=True)
class PanTiltJoints:
    """The pan and tilt joints of a head."""

    robot: str
    pan_joint: str
    tilt_joint: str


@dataclass(frozen=True)
class PanTiltLinks:
    """The pan and tilt links of a head."""

    robot: str
    pan_link: str
    tilt_link: str


@dataclass(frozen=True)
class TorsoLinkJoint:
    """The torso's link and the joint that lifts it."""

    robot: str
    link: str
    joint: str


_D = Source.DESCRIPTION
ROBOT = Predicate("robot", Robot, _D, "the robot's name", Need.ROBOT)
ROBOT_DESCRIPTION = Predicate(
    "robot_description", RobotDescriptionFact, _D, "the description object", Need.ROBOT
)
ROBOT_BASE_FRAME = Predicate(
    "robot_base_frame", RobotFrame, _D, "the frame of the base, the URDF root", Need.ROBOT
)
ROBOT_ODOM_FRAME = Predicate(
    "robot_odom_frame", RobotFrame, _D, "the odometry frame the base moves in", Need.ROBOT
)
FLYING_ROBOT = Predicate("flying_robot", Robot, _D, "the robot flies (flying motions)")
ROBOT_TORSO_LINK_JOINT = Predicate(
    "robot_torso_link_joint", TorsoLinkJoint, _D, "the torso link and its lifting joint"
)
CAMERA_FRAME = Predicate("camera_frame", RobotFrame, _D, "a camera's optical frame")
CAMERA_MINIMAL_HEIGHT = Predicate(
    "camera_minimal_height", CameraHeight, _D, "the camera's height, torso down"
)
CAMERA_MAXIMAL_HEIGHT = Predicate(
    "camera_maximal_height", CameraHeight, _D, "the camera's height, torso up"
)
CAMERA_HORIZONTAL_ANGLE = Predicate(
    "camera_horizontal_angle", CameraAngle, _D, "the camera's horizontal field of view"
)
CAMERA_VERTICAL_ANGLE = Predicate(
    "camera_vertical_angle", CameraAngle, _D, "the camera's vertical field of view"
)
ARM = Predicate("arm", Arm, _D, "a manipulating arm (the neck arm is none)")
ARM_JOINTS = Predicate("arm_joints", ArmJoints, _D, "the arm's joints, base first", Need.ARM)
ARM_LINKS = Predicate("arm_links", ArmLinks, _D, "the arm's links, base first", Need.ARM)
HAND_LINKS = Predicate("hand_links", ArmLinks, _D, "the wrist and every link below it", Need.ARM)
END_EFFECTOR_LINK = Predicate(
    "end_effector_link", ArmLink, _D, "the link a grasped object is attached to", Need.ARM
)
ROBOT_TOOL_FRAME = Predicate(
    "robot_tool_frame", ArmFrame, _D, "the frame arm motions put at the target", Need.ARM
)
GRIPPER_JOINT = Predicate("gripper_joint", ArmJoint, _D, "a joint of the arm's gripper")
GRIPPER_LINK = Predicate("gripper_link", ArmLink, _D, "a link the gripper's joints move")
GRIPPER_MAX_OPENING = Predicate(
    "gripper_max_opening", GripperOpening, _D, "the widest gap between the fingers"
)
ARM_WORKING_DIRECTION = Predicate(
    "arm_working_direction",
    ArmDirection,
    _D,
    "the arm's working direction from its reach envelope (Stretch's: -pi/2)",
)
ROBOT_ARMS_PARKING_JOINT_STATES = Predicate(
    "robot_arms_parking_joint_states",
    ParkingPose,
    _D,
    "the arm's parking configuration (empty: stays as it is)",
    Need.ARM,
)
ROBOT_ARMS_CARRYING_JOINT_STATES = Predicate(
    "robot_arms_carrying_joint_states",
    CarryingPose,
    _D,
    "the arm's configuration to carry an object in",
    Need.ARM,
)
ROBOT_NECK_LINKS = Predicate("robot_neck_links", RobotLinks, _D, "the links of the neck")
ROBOT_NECK_JOINTS = Predicate("robot_neck_joints", RobotJoints, _D, "the joints of the neck")
ROBOT_NECK_PARKING_JOINT_STATES = Predicate(
    "robot_neck_parking_joint_states", NeckParkingPose, _D, "the neck's parking configuration"
)
ROBOT_PAN_TILT_LINKS = Predicate(
    "robot_pan_tilt_links", PanTiltLinks, _D, "the links a pan-tilt head turns"
)
ROBOT_PAN_TILT_JOINTS = Predicate(
    "robot_pan_tilt_joints", PanTiltJoints, _D, "the joints of a pan-tilt head"
)
JOINT_TYPE = Predicate("joint_type", JointType, _D, "a URDF joint's type (revolute, ...)")
JOINT_PARENT = Predicate("joint_parent", JointLink, _D, "a URDF joint's parent link")
JOINT_CHILD = Predicate("joint_child", JointLink, _D, "a URDF joint's child link")
JOINT_AXIS = Predicate("joint_axis", JointAxis, _D, "a URDF joint's axis [x, y, z]")
JOINT_ORIGIN = Predicate("joint_origin", JointOrigin, _D, "a URDF joint's origin pose")
JOINT_LOWER_LIMIT = Predicate("joint_lower_limit", JointLimit, _D, "a joint's lower limit")
JOINT_UPPER_LIMIT = Predicate("joint_upper_limit", JointLimit, _D, "a joint's upper limit")
JOINT_MIMIC = Predicate("joint_mimic", JointMimic, _D, "a joint following another")

DESCRIPTION_PREDICATES: tuple[Predicate[Any], ...] = (
    ROBOT,
    ROBOT_DESCRIPTION,
    ROBOT_BASE_FRAME,
    ROBOT_ODOM_FRAME,
    FLYING_ROBOT,
    ROBOT_TORSO_LINK_JOINT,
    CAMERA_FRAME,
    CAMERA_MINIMAL_HEIGHT,
    CAMERA_MAXIMAL_HEIGHT,
    CAMERA_HORIZONTAL_ANGLE,
    CAMERA_VERTICAL_ANGLE,
    ARM,
    ARM_JOINTS,
    ARM_LINKS,
    HAND_LINKS,
    END_EFFECTOR_LINK,
    ROBOT_TOOL_FRAME,
    GRIPPER_JOINT,
    GRIPPER_LINK,
    GRIPPER_MAX_OPENING,
    ARM_WORKING_DIRECTION,
    ROBOT_ARMS_PARKING_JOINT_STATES,
    ROBOT_ARMS_CARRYING_JOINT_STATES,
    ROBOT_NECK_LINKS,
    ROBOT_NECK_JOINTS,
    ROBOT_NECK_PARKING_JOINT_STATES,
    ROBOT_PAN_TILT_LINKS,
    ROBOT_PAN_TILT_JOINTS,
    JOINT_TYPE,
    JOINT_PARENT,
    JOINT_CHILD,
    JOINT_AXIS,
    JOINT_ORIGIN,
    JOINT_LOWER_LIMIT,
    JOINT_UPPER_LIMIT,
    JOINT_MIMIC,
)

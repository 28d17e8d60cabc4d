"""A robot description as facts of CRAM's robot interface predicates, plus URDF facts.

The predicates, their arguments and meanings are rows of the predicate table
(``robocram.knowledge.robot_predicates``); each fact here is built from its row's typed
dataclass, so a misspelt predicate or a missing argument fails type checking. The
predicates are declared (extendable, without clauses) in the fact group
``robot_interface``; each robot's facts live in its own group ``<name>_description``, so
several robots share one knowledge base and users add their own rules in further groups.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any, Protocol

from robocram.knowledge import JointStates, Source, check_facts, indicators_of
from robocram.knowledge import robot_predicates as rp
from robocram.logic.terms import Term
from robocram.robots.arm_envelope import working_yaw
from robocram.robots.description import ArmDescription, LoadedDescription, RobotDescription
from robocram.robots.loading import load_description
from robocram.robots.robot_model import RobotModel

INTERFACE_GROUP = "robot_interface"
INTERFACE_PREDICATES: tuple[str, ...] = indicators_of(Source.DESCRIPTION)


class FactGroupSink(Protocol):
    """What ``install_description`` needs of a knowledge base."""

    def add_fact_group(self, group: str, clauses: Any, extendable: Sequence[str] = ...) -> Any:
        """(Re)load fact group ``group`` with ``clauses``."""


def _states(values: Mapping[str, float]) -> JointStates:
    return tuple((joint, float(value)) for joint, value in values.items())


def _robot_facts(desc: RobotDescription) -> Iterator[Term]:
    r = desc.name
    yield rp.ROBOT.fact(rp.Robot(r))
    yield rp.ROBOT_DESCRIPTION.fact(rp.RobotDescriptionFact(r, desc))
    yield rp.ROBOT_BASE_FRAME.fact(rp.RobotFrame(r, desc.base_frame))
    yield rp.ROBOT_ODOM_FRAME.fact(rp.RobotFrame(r, desc.odom_frame))
    if desc.flying:
        yield rp.FLYING_ROBOT.fact(rp.Robot(r))
    if desc.torso_link is not None and desc.torso_joint is not None:
        torso = rp.TorsoLinkJoint(r, desc.torso_link, desc.torso_joint)
        yield rp.ROBOT_TORSO_LINK_JOINT.fact(torso)
    for camera in desc.cameras:
        yield rp.CAMERA_FRAME.fact(rp.RobotFrame(r, camera.frame))
        if camera.minimal_height is not None:  # loading derives both heights
            yield rp.CAMERA_MINIMAL_HEIGHT.fact(rp.CameraHeight(r, camera.minimal_height))
        if camera.maximal_height is not None:
            yield rp.CAMERA_MAXIMAL_HEIGHT.fact(rp.CameraHeight(r, camera.maximal_height))
        yield rp.CAMERA_HORIZONTAL_ANGLE.fact(rp.CameraAngle(r, camera.horizontal_fov))
        yield rp.CAMERA_VERTICAL_ANGLE.fact(rp.CameraAngle(r, camera.vertical_fov))


def _arm_facts(
    r: str, arm: ArmDescription, is_neck: bool, model: RobotModel | None = None
) -> Iterator[Term]:
    a = arm.name
    if not is_neck:
        yield rp.ARM.fact(rp.Arm(r, a))
    yield rp.ARM_JOINTS.fact(rp.ArmJoints(r, a, tuple(arm.joints)))
    yield rp.ARM_LINKS.fact(rp.ArmLinks(r, a, tuple(arm.links)))
    yield rp.HAND_LINKS.fact(rp.ArmLinks(r, a, tuple(arm.hand_links)))
    yield rp.END_EFFECTOR_LINK.fact(rp.ArmLink(r, a, arm.end_effector_link))
    yield rp.ROBOT_TOOL_FRAME.fact(rp.ArmFrame(r, a, arm.tool_frame))
    yield from (rp.GRIPPER_JOINT.fact(rp.ArmJoint(r, a, j)) for j in arm.gripper_joints)
    yield from (rp.GRIPPER_LINK.fact(rp.ArmLink(r, a, link)) for link in arm.gripper_links)
    if arm.gripper is not None and arm.gripper.max_opening is not None:
        yield rp.GRIPPER_MAX_OPENING.fact(rp.GripperOpening(r, a, arm.gripper.max_opening))
    if not is_neck and model is not None and arm.joints:
        yield rp.ARM_WORKING_DIRECTION.fact(rp.ArmDirection(r, a, working_yaw(model, arm)))
    parking, carrying = _states(arm.parking), _states(arm.carrying)
    yield rp.ROBOT_ARMS_PARKING_JOINT_STATES.fact(rp.ParkingPose(r, a, parking))
    yield rp.ROBOT_ARMS_CARRYING_JOINT_STATES.fact(rp.CarryingPose(r, a, carrying))


def _pan_tilt(desc: RobotDescription) -> tuple[rp.PanTiltLinks, rp.PanTiltJoints] | None:
    """The head's links and joints; loading derives the links, so None only before it."""
    pt = desc.pan_tilt
    if pt is None or pt.pan_link is None or pt.tilt_link is None:
        return None
    r = desc.name
    return rp.PanTiltLinks(r, pt.pan_link, pt.tilt_link), rp.PanTiltJoints(
        r, pt.pan_joint, pt.tilt_joint
    )


def _head_facts(desc: RobotDescription) -> Iterator[Term]:
    r, head = desc.name, _pan_tilt(desc)
    if head is not None:
        yield rp.ROBOT_PAN_TILT_LINKS.fact(head[0])
        yield rp.ROBOT_PAN_TILT_JOINTS.fact(head[1])
    neck = desc.arms.get(desc.neck_arm) if desc.neck_arm is not None else None
    if neck is not None:
        yield rp.ROBOT_NECK_LINKS.fact(rp.RobotLinks(r, tuple(neck.links)))
        yield rp.ROBOT_NECK_JOINTS.fact(rp.RobotJoints(r, tuple(neck.joints)))
    elif head is not None:
        links, joints = head
        yield rp.ROBOT_NECK_LINKS.fact(rp.RobotLinks(r, (links.pan_link, links.tilt_link)))
        yield rp.ROBOT_NECK_JOINTS.fact(rp.RobotJoints(r, (joints.pan_joint, joints.tilt_joint)))
    if desc.neck_parking:
        states = _states(desc.neck_parking)
        yield rp.ROBOT_NECK_PARKING_JOINT_STATES.fact(rp.NeckParkingPose(r, states))


def _urdf_facts(r: str, model: RobotModel) -> Iterator[Term]:
    for joint in model.joints.values():
        j = joint.name
        yield rp.JOINT_TYPE.fact(rp.JointType(r, j, joint.type))
        yield rp.JOINT_PARENT.fact(rp.JointLink(r, j, joint.parent))
        yield rp.JOINT_CHILD.fact(rp.JointLink(r, j, joint.child))
        yield rp.JOINT_AXIS.fact(rp.JointAxis(r, j, tuple(joint.axis)))
        yield rp.JOINT_ORIGIN.fact(rp.JointOrigin(r, j, joint.origin))
        if joint.lower is not None and joint.upper is not None:
            yield rp.JOINT_LOWER_LIMIT.fact(rp.JointLimit(r, j, joint.lower))
            yield rp.JOINT_UPPER_LIMIT.fact(rp.JointLimit(r, j, joint.upper))
        if joint.mimic is not None:
            m = joint.mimic
            yield rp.JOINT_MIMIC.fact(rp.JointMimic(r, j, m.joint, m.multiplier, m.offset))


def description_facts(desc: LoadedDescription) -> list[Term]:
    """All facts of a loaded description, robot facts first."""
    facts = list(_robot_facts(desc))
    for arm in desc.arms.values():
        facts.extend(_arm_facts(desc.name, arm, arm.name == desc.neck_arm, desc.model))
    facts.extend(_head_facts(desc))
    facts.extend(_urdf_facts(desc.name, desc.model))
    return facts


def install_description(kb: FactGroupSink, desc: RobotDescription | str) -> LoadedDescription:
    """Load ``desc`` (checking it if needed) as fact group ``<name>_description`` of ``kb``.

    Returns the loaded description, so ``install_description(kb, "pr2")`` also hands back
    the checked PR2.

    Raises:
        MissingFactsError: the facts lack a predicate the table requires (each named
            with its meaning).
    """
    loaded = desc if isinstance(desc, LoadedDescription) else load_description(desc)
    facts = description_facts(loaded)
    check_facts(facts)
    kb.add_fact_group(INTERFACE_GROUP, [], extendable=list(INTERFACE_PREDICATES))
    kb.add_fact_group(f"{loaded.name}_description", facts)
    return loaded

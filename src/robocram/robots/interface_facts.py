"""A robot description as facts of CRAM's robot interface predicates, plus URDF facts.

The predicates are declared (extendable, without clauses) in the fact group
``robot_interface``; each robot's facts live in its own group ``<name>_description``, so
several robots share one knowledge base and users add their own rules in further groups.
``gripper_max_opening(R, Arm, Metres)`` is the widest gap between the fingers, for grasp
models that compare it with an object. Lists are Prolog lists; joint states are lists of
``[Joint, Value]`` pairs [rad | m].
The neck arm of a robot (``neck_arm``) answers ``arm_joints/3`` and the like, but not
``arm/2``: plans that pick with "any arm" must not pick with the neck.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import Any, Protocol

from robocram.logic.terms import Term, make_list
from robocram.robots.description import ArmDescription, LoadedDescription, RobotDescription
from robocram.robots.loading import load_description
from robocram.robots.robot_model import RobotModel

INTERFACE_GROUP = "robot_interface"
INTERFACE_PREDICATES: tuple[str, ...] = (
    "arm/2",
    "arm_joints/3",
    "arm_links/3",
    "camera_frame/2",
    "camera_horizontal_angle/2",
    "camera_maximal_height/2",
    "camera_minimal_height/2",
    "camera_vertical_angle/2",
    "end_effector_link/3",
    "flying_robot/1",
    "gripper_joint/3",
    "gripper_link/3",
    "gripper_max_opening/3",
    "hand_links/3",
    "joint_axis/3",
    "joint_child/3",
    "joint_lower_limit/3",
    "joint_mimic/5",
    "joint_origin/3",
    "joint_parent/3",
    "joint_type/3",
    "joint_upper_limit/3",
    "robot/1",
    "robot_arms_carrying_joint_states/3",
    "robot_arms_parking_joint_states/3",
    "robot_base_frame/2",
    "robot_description/2",
    "robot_neck_joints/2",
    "robot_neck_links/2",
    "robot_neck_parking_joint_states/2",
    "robot_odom_frame/2",
    "robot_pan_tilt_joints/3",
    "robot_pan_tilt_links/3",
    "robot_tool_frame/3",
    "robot_torso_link_joint/3",
)


class FactGroupSink(Protocol):
    """What ``install_description`` needs of a knowledge base."""

    def add_fact_group(self, group: str, clauses: Any, extendable: Sequence[str] = ...) -> Any:
        """(Re)load fact group ``group`` with ``clauses``."""


def _fact(name: str, *args: Any) -> Term:
    return Term(name, args)


def _states(values: Mapping[str, float]) -> Any:
    return make_list([make_list([joint, float(value)]) for joint, value in values.items()])


def _robot_facts(desc: RobotDescription) -> Iterator[Term]:
    r = desc.name
    yield _fact("robot", r)
    yield _fact("robot_description", r, desc)
    yield _fact("robot_base_frame", r, desc.base_frame)
    yield _fact("robot_odom_frame", r, desc.odom_frame)
    if desc.flying:
        yield _fact("flying_robot", r)
    if desc.torso_link is not None and desc.torso_joint is not None:
        yield _fact("robot_torso_link_joint", r, desc.torso_link, desc.torso_joint)
    for camera in desc.cameras:
        yield _fact("camera_frame", r, camera.frame)
        yield _fact("camera_minimal_height", r, camera.minimal_height)
        yield _fact("camera_maximal_height", r, camera.maximal_height)
        yield _fact("camera_horizontal_angle", r, camera.horizontal_fov)
        yield _fact("camera_vertical_angle", r, camera.vertical_fov)


def _arm_facts(r: str, arm: ArmDescription, is_neck: bool) -> Iterator[Term]:
    a = arm.name
    if not is_neck:
        yield _fact("arm", r, a)
    yield _fact("arm_joints", r, a, make_list(arm.joints))
    yield _fact("arm_links", r, a, make_list(arm.links))
    yield _fact("hand_links", r, a, make_list(arm.hand_links))
    yield _fact("end_effector_link", r, a, arm.end_effector_link)
    yield _fact("robot_tool_frame", r, a, arm.tool_frame)
    yield from (_fact("gripper_joint", r, a, j) for j in arm.gripper_joints)
    yield from (_fact("gripper_link", r, a, link) for link in arm.gripper_links)
    if arm.gripper is not None and arm.gripper.max_opening is not None:
        yield _fact("gripper_max_opening", r, a, arm.gripper.max_opening)
    yield _fact("robot_arms_parking_joint_states", r, a, _states(arm.parking))
    yield _fact("robot_arms_carrying_joint_states", r, a, _states(arm.carrying))


def _head_facts(desc: RobotDescription) -> Iterator[Term]:
    r, pt = desc.name, desc.pan_tilt
    if pt is not None:
        yield _fact("robot_pan_tilt_links", r, pt.pan_link, pt.tilt_link)
        yield _fact("robot_pan_tilt_joints", r, pt.pan_joint, pt.tilt_joint)
    neck = desc.arms.get(desc.neck_arm) if desc.neck_arm is not None else None
    if neck is not None:
        yield _fact("robot_neck_links", r, make_list(neck.links))
        yield _fact("robot_neck_joints", r, make_list(neck.joints))
    elif pt is not None:
        yield _fact("robot_neck_links", r, make_list([pt.pan_link, pt.tilt_link]))
        yield _fact("robot_neck_joints", r, make_list([pt.pan_joint, pt.tilt_joint]))
    if desc.neck_parking:
        yield _fact("robot_neck_parking_joint_states", r, _states(desc.neck_parking))


def _urdf_facts(r: str, model: RobotModel) -> Iterator[Term]:
    for joint in model.joints.values():
        j = joint.name
        yield _fact("joint_type", r, j, joint.type)
        yield _fact("joint_parent", r, j, joint.parent)
        yield _fact("joint_child", r, j, joint.child)
        yield _fact("joint_axis", r, j, make_list(list(joint.axis)))
        yield _fact("joint_origin", r, j, joint.origin)
        if joint.lower is not None and joint.upper is not None:
            yield _fact("joint_lower_limit", r, j, joint.lower)
            yield _fact("joint_upper_limit", r, j, joint.upper)
        if joint.mimic is not None:
            m = joint.mimic
            yield _fact("joint_mimic", r, j, m.joint, m.multiplier, m.offset)


def description_facts(desc: LoadedDescription) -> list[Term]:
    """All facts of a loaded description, robot facts first."""
    facts = list(_robot_facts(desc))
    for arm in desc.arms.values():
        facts.extend(_arm_facts(desc.name, arm, arm.name == desc.neck_arm))
    facts.extend(_head_facts(desc))
    facts.extend(_urdf_facts(desc.name, desc.model))
    return facts


def install_description(kb: FactGroupSink, desc: RobotDescription | str) -> LoadedDescription:
    """Load ``desc`` (checking it if needed) as fact group ``<name>_description`` of ``kb``.

    Returns the loaded description, so ``install_description(kb, "pr2")`` also hands back
    the checked PR2.
    """
    loaded = desc if isinstance(desc, LoadedDescription) else load_description(desc)
    kb.add_fact_group(INTERFACE_GROUP, [], extendable=list(INTERFACE_PREDICATES))
    kb.add_fact_group(f"{loaded.name}_description", description_facts(loaded))
    return loaded

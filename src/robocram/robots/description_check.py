"""Check a robot description against its model: every named joint, link and frame must exist.

All problems are collected and reported together, each with the closest existing names.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import replace

from robocram.robots.description import ArmDescription, RobotDescription
from robocram.robots.errors import (
    DescriptionCheckError,
    JointValueError,
    NameProblem,
    closest_names,
)
from robocram.robots.robot_model import RobotModel

_LIMIT_SLACK = 1e-6  # [rad | m] tolerance on description values at a limit


class _Checker:
    def __init__(self, model: RobotModel) -> None:
        self.model = model
        self.problems: list[NameProblem] = []

    def links(self, names: Iterable[str | None], where: str, kind: str = "link") -> None:
        for name in names:
            if name is not None and name not in self.model.links:
                close = closest_names(name, self.model.links)
                self.problems.append(NameProblem(kind, name, where, close))

    def joints(self, names: Iterable[str | None], where: str) -> None:
        for name in names:
            if name is None:
                continue
            joint = self.model.joints.get(name)
            if joint is None:
                close = closest_names(name, self.model.joints)
                self.problems.append(NameProblem("joint", name, where, close))
            elif not joint.movable:
                close = closest_names(name, (j.name for j in self.model.movable_joints()))
                self.problems.append(
                    NameProblem(f"movable joint ({joint.type})", name, where, close)
                )

    def arm(self, key: str, arm: ArmDescription) -> None:
        where = f"arms[{key!r}]"
        if arm.name != key:
            self.problems.append(NameProblem("arm name", arm.name, where, (key,)))
        self.links([arm.end_effector_link, arm.base_link], f"{where}.end_effector_link/base_link")
        self.links([arm.tool_frame], f"{where}.tool_frame", kind="frame")
        self.links(arm.links, f"{where}.links")
        self.links(arm.gripper_links, f"{where}.gripper_links")
        self.links(arm.hand_links, f"{where}.hand_links")
        self.joints(arm.joints, f"{where}.joints")
        self.joints(arm.gripper_joints, f"{where}.gripper_joints")
        self.joints(arm.parking, f"{where}.parking")
        self.joints(arm.carrying, f"{where}.carrying")


def check_names(desc: RobotDescription, model: RobotModel) -> None:
    """Raise :class:`DescriptionCheckError` listing every name ``model`` does not have."""
    check = _Checker(model)
    check.links([desc.base_frame, desc.torso_link], "base_frame/torso_link")
    check.joints([desc.torso_joint], "torso_joint")
    for key, arm in desc.arms.items():
        check.arm(key, arm)
    for i, camera in enumerate(desc.cameras):
        check.links([camera.frame], f"cameras[{i}].frame", kind="frame")
    if desc.pan_tilt is not None:
        pt = desc.pan_tilt
        check.links([pt.pan_link, pt.tilt_link], "pan_tilt links")
        check.joints([pt.pan_joint, pt.tilt_joint], "pan_tilt joints")
    check.joints(desc.neck_parking, "neck_parking")
    if desc.neck_arm is not None and desc.neck_arm not in desc.arms:
        close = closest_names(desc.neck_arm, desc.arms)
        check.problems.append(NameProblem("arm", desc.neck_arm, "neck_arm", close))
    if check.problems:
        raise DescriptionCheckError(desc.name, model.source, check.problems)


def infer_arm(arm: ArmDescription, model: RobotModel) -> ArmDescription:
    """Fill an arm's empty joints and links from the chain ``base_link..end_effector_link``."""
    if arm.base_link is None:
        if not arm.joints:
            raise DescriptionCheckError(
                arm.name,
                model.source,
                [
                    NameProblem(
                        "base_link", "None", f"arms[{arm.name!r}]; give joints or a base_link", ()
                    )
                ],
            )
        links = arm.links or tuple(model.joints[j].child for j in arm.joints)
        return _replace_arm(arm, arm.joints, links)
    chain = model.chain(arm.base_link, arm.end_effector_link)
    movable = tuple(j.name for j in chain if j.movable)
    stray = [j for j in arm.joints if j not in movable]
    if stray:
        problems = [
            NameProblem("chain joint", j, f"arms[{arm.name!r}].joints", movable[:3]) for j in stray
        ]
        raise DescriptionCheckError(arm.name, model.source, problems)
    links = arm.links or tuple(j.child for j in chain)
    return _replace_arm(arm, arm.joints or movable, links)


def _replace_arm(
    arm: ArmDescription, joints: tuple[str, ...], links: tuple[str, ...]
) -> ArmDescription:
    return replace(arm, joints=joints, links=links)


def check_values(robot: str, model: RobotModel, states: Mapping[str, float]) -> None:
    """Raise :class:`JointValueError` for a joint value outside the joint's limits."""
    for name, value in states.items():
        joint = model.joints[name]
        lower = -math.inf if joint.lower is None else joint.lower
        upper = math.inf if joint.upper is None else joint.upper
        if not lower - _LIMIT_SLACK <= value <= upper + _LIMIT_SLACK:
            raise JointValueError(robot, name, value, lower, upper)

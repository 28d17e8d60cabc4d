"""How a robot turns its camera towards a target: which joints looking may move.

A pan-tilt head or a neck arm is described; other robots are read off the joints between
the camera and the root link. A camera moved only by an arm's joints (a wrist camera, no
neck: the Panda) looks by moving that arm to a viewing pose; a camera moved by one joint
that belongs to no arm (Baxter's head, which only pans) looks by turning that joint and
accepts the tilt it cannot change. A camera no joint moves (the torso aside) cannot look
around: a look only checks the target is in view (``projection/look_fixed.py``). A neck
arm that is a manipulator's arm (its joints all the arm's) looks as that arm does.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from robocram.robots.description import LoadedDescription, RobotDescription

MeansKind = Literal["pan_tilt", "neck_arm", "arm", "pan"]


@dataclass(frozen=True)
class LookingMeans:
    """What turns the camera: ``arm`` names the arm carrying it, ``joint``/``link`` the
    one joint (and its child link) of a head that only pans."""

    kind: MeansKind
    arm: str | None = None
    joint: str | None = None
    link: str | None = None


def looking_means(desc: LoadedDescription) -> LookingMeans | None:
    """How ``desc``'s first camera is aimed, or None when nothing can turn it."""
    if not desc.cameras:
        return None
    if desc.pan_tilt is not None:
        return LookingMeans("pan_tilt")
    if desc.neck_arm is not None:
        carrier = _manipulator_as_neck(desc, desc.neck_arm)
        return LookingMeans("arm", arm=carrier) if carrier else LookingMeans("neck_arm")
    model = desc.model
    chain = model.chain(model.root_link, desc.cameras[0].frame)
    moving = [
        j for j in chain if j.type != "fixed" and j.mimic is None and j.name != desc.torso_joint
    ]
    if not moving:
        return None
    names = {j.name for j in moving}
    for key, arm in desc.arms.items():
        if names <= set(arm.joints):
            return LookingMeans("arm", arm=key)
    if len(moving) == 1 and moving[0].type in ("revolute", "continuous"):
        return LookingMeans("pan", joint=moving[0].name, link=moving[0].child)
    return None


def _manipulator_as_neck(desc: LoadedDescription, neck: str) -> str | None:
    """The arm with a gripper whose joints are all the neck arm's, or None: a camera on a
    manipulator's wrist (the Donbot's) described as a neck looks as an arm's camera does,
    from viewing poses the robot's own body does not hide, not from where the arm is parked
    beside the base."""
    joints = set(desc.arms[neck].joints) if neck in desc.arms else set()
    for key, arm in desc.arms.items():
        if key != neck and arm.gripper is not None and joints and joints == set(arm.joints):
            return key
    return None


def with_looking(desc: RobotDescription, resources: tuple[str, ...]) -> tuple[str, ...]:
    """``resources`` and, where a camera can be turned without a described head or nothing
    turns it on a robot that does not fly (a look then checks that the target is in
    view), ``ptu`` (after ``perception``, where a head's module starts)."""
    if "ptu" in resources or not isinstance(desc, LoadedDescription):
        return resources
    if "perception" not in resources or (desc.flying and looking_means(desc) is None):
        return resources  # a flying robot turns itself to look
    at = resources.index("perception") + 1
    return (*resources[:at], "ptu", *resources[at:])


def head_joints(desc: RobotDescription) -> set[str]:
    """The joints a ``looking`` motion may set by value (its ``configuration``): a pan-tilt
    head's, a neck arm's and those of the neck's parking configuration."""
    joints = set(desc.neck_parking)
    if desc.pan_tilt is not None:
        joints |= {desc.pan_tilt.pan_joint, desc.pan_tilt.tilt_joint}
    neck = desc.arms.get(desc.neck_arm) if desc.neck_arm is not None else None
    if neck is not None:
        joints |= set(neck.joints)
    return joints

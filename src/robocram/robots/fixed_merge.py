"""Fold links hung on fixed joints into their parents, keeping their frames as offsets.

Physics engines cap the links of one body (PyBullet: 128). Robots such as the dual-arm
TIAGo exceed it mostly with fixed links (sensors, covers, tool frames). Merging them keeps
every movable joint and every shape; the merged links stay reachable as *frames*: a host
link that remains a body link and the frame's fixed pose in it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Collision, Inertial, Joint, Link, Visual
from robocram.tf import Pose


@dataclass(frozen=True)
class MergedModel:
    """A model with fixed links folded in, and where each folded link's frame now lies."""

    model: RobotModel
    frames: dict[str, tuple[str, Pose]]  # folded link -> (host link, its pose in the host)


def merge_fixed_links(model: RobotModel, keep: frozenset[str] = frozenset()) -> MergedModel:
    """Fold every child of a fixed joint (except ``keep``) into its parent, recursively."""
    frames: dict[str, tuple[str, Pose]] = {}
    links = dict(model.links)
    joints: dict[str, Joint] = {}
    for joint in _parents_first(model):
        host, offset = frames.get(joint.parent, (joint.parent, Pose()))
        moved = replace(joint, parent=host, origin=offset * joint.origin)
        if joint.type != "fixed" or joint.child in keep:
            joints[joint.name] = moved
            continue
        frames[joint.child] = (host, moved.origin)
        links[host] = _fold(links[host], links.pop(joint.child), moved.origin)
    merged = RobotModel(model.name, links, joints, model.source)
    return MergedModel(merged, frames)


def _parents_first(model: RobotModel) -> list[Joint]:
    order: list[Joint] = []
    todo = [model.root_link]
    children: dict[str, list[Joint]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint)
    while todo:
        for joint in children.get(todo.pop(), []):
            order.append(joint)
            todo.append(joint.child)
    return order


def _fold(host: Link, guest: Link, host_T_guest: Pose) -> Link:
    """``host`` carrying ``guest``'s shapes and mass, ``guest`` at ``host_T_guest``."""
    visuals = tuple(Visual(v.geometry, host_T_guest * v.origin, v.name, v.material, v.rgba)
                    for v in guest.visuals)  # fmt: skip
    collisions = tuple(
        Collision(c.geometry, host_T_guest * c.origin, c.name) for c in guest.collisions
    )
    inertial = _combined(host.inertial, guest.inertial, host_T_guest)
    return Link(host.name, host.visuals + visuals, host.collisions + collisions, inertial)


def _tensor(inertial: Inertial) -> np.ndarray:
    ixx, ixy, ixz, iyy, iyz, izz = inertial.inertia
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])


def _combined(a: Inertial | None, b: Inertial | None, host_T_b: Pose) -> Inertial | None:
    """Mass, centre and inertia of two bodies as one, in the host frame (parallel axes)."""
    if b is None or b.mass <= 0:
        return a
    b_in_host = replace(b, origin=host_T_b * b.origin)
    if a is None or a.mass <= 0:
        return b_in_host
    mass = a.mass + b.mass
    centres = [np.array(i.origin.position) for i in (a, b_in_host)]
    centre = (a.mass * centres[0] + b.mass * centres[1]) / mass
    total = np.zeros((3, 3))
    for part, c in zip((a, b_in_host), centres, strict=True):
        rot = part.origin.matrix()[:3, :3]
        d = c - centre
        total += rot @ _tensor(part) @ rot.T + part.mass * (d @ d * np.eye(3) - np.outer(d, d))
    values = (total[0, 0], total[0, 1], total[0, 2], total[1, 1], total[1, 2], total[2, 2])
    return Inertial(mass, tuple(float(v) for v in values), Pose(tuple(float(c) for c in centre)))  # type: ignore[arg-type]

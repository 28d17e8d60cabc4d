"""A body's links and joints by slot: the pybullet reads and writes of one body's joints.

An object may be one pybullet body or several (a model of more than 127 links is cut
into parts); its links and joints are numbered by *slot* across them
(:meth:`~robocram.world.world_object.WorldObject.slot`). These functions name the slots
of a new body, and read and write joints by slot with one pybullet call per body, for
the world's tables and parts.
"""

from __future__ import annotations

from collections.abc import Mapping

from robocram.world.errors import UnknownLinkError
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import WorldObject


def index_body(handle: WorldObject, body: int, cid: int) -> None:
    """Name ``body``'s links and joints in ``handle``'s tables, by slot."""
    base_name = pybullet.getBodyInfo(body, physicsClientId=cid)[0].decode()
    handle.link_index[base_name] = handle.slot(body, -1)
    for i in range(pybullet.getNumJoints(body, physicsClientId=cid)):
        info = pybullet.getJointInfo(body, i, physicsClientId=cid)
        handle.joint_index[info[1].decode()] = handle.slot(body, i)
        handle.link_index[info[12].decode()] = handle.slot(body, i)
        if info[2] in (pybullet.JOINT_REVOLUTE, pybullet.JOINT_PRISMATIC):
            handle.movable_joints.append(info[1].decode())


def part_joint_states(handle: WorldObject, names: list[str], cid: int) -> dict[str, float]:
    """:meth:`WorldTables.joint_states` of an object of several bodies, one call per body."""
    by_body: dict[int, list[tuple[str, int]]] = {}
    for name in names:
        body, index = handle.locate(handle.joint_index[name])
        by_body.setdefault(body, []).append((name, index))
    values: dict[str, float] = {}
    for body, joints in by_body.items():
        states = pybullet.getJointStates(body, [i for _, i in joints], physicsClientId=cid)
        values.update((n, float(s[0])) for (n, _), s in zip(joints, states or (), strict=True))
    return {name: values[name] for name in names}


def reset_slots(handle: WorldObject, values: Mapping[int, float], cid: int) -> None:
    """:func:`_reset_joints` by slot, for each body of ``handle``."""
    if not handle.parts:
        reset_joints(handle.body_id, values, cid)
        return
    by_body: dict[int, dict[int, float]] = {}
    for slot, value in values.items():
        body, index = handle.locate(slot)
        by_body.setdefault(body, {})[index] = value
    for body, part in by_body.items():
        reset_joints(body, part, cid)


def reset_joints(body: int, values: Mapping[int, float], cid: int) -> None:
    """Put one-DoF joints (by index) at ``values`` [rad | m] at rest, in one call."""
    if values:
        pybullet.resetJointStatesMultiDof(
            body,
            list(values),
            targetValues=[[v] for v in values.values()],
            targetVelocities=[[0.0]] * len(values),
            physicsClientId=cid,
        )


def link_slot(handle: WorldObject, link: str) -> int:
    """The slot of ``handle``'s link (or added frame) called ``link``; unknown: an error."""
    index = handle.link_index.get(link)
    if index is None:
        raise UnknownLinkError(handle.name, link, handle.link_index)
    return index

"""How fast each moving link can move per unit joint change, as the robot is posed now.

A checker that walks a long sweep asks, at each checked configuration, for the lever of
every joint on every moving link: the distance from the joint's axis to the link's frame
plus the link's radius (1 for a prismatic joint, 0 for a joint the link is not below).
:class:`LeverData` holds what does not change along a sweep; the frames come from the
checker (PyBullet's links or pinocchio's frames), so both checkers share the arithmetic.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.mimic_family import mimic_family
from robocram.motion.travel_bound import link_radii
from robocram.robots import RobotModel
from robocram.world import RobotHandle


@dataclass(frozen=True)
class LeverData:
    """What :meth:`levers` needs beyond the frames: rows, axes, radii, masks."""

    frame_links: tuple[str, ...]  # links whose frames are read per configuration
    row: dict[str, int]  # moving link -> its row below
    carriers: dict[str, str]  # held object -> the link it rides on
    centre_rows: NDArray[np.intp]  # per moving link: its row in frame_links
    joint_rows: NDArray[np.intp]  # per joint: its child link's row in frame_links
    local_axes: FloatArray  # (joints, 3) each joint's axis in its child link's frame
    prismatic: NDArray[np.bool_]  # (joints,)
    radii: FloatArray  # (links,) [m] about each link's frame, held objects included
    below: NDArray[np.bool_]  # (links, joints) whether the joint moves the link
    after: NDArray[np.bool_]  # (joints, joints) whether joint k's child moves with joint i
    chains: FloatArray  # (links, joints) [m] the most from the joint's origin to the link's
    # frame, whatever the joints between do (the rigid lengths between; 0 where not below)
    _rows: dict[tuple[str, ...], NDArray[np.intp]] = field(default_factory=dict)
    _masks: dict[bytes, tuple[FloatArray, FloatArray]] = field(default_factory=dict)

    @classmethod
    def of(cls, robot: RobotHandle, joints: Sequence[str], moving: Sequence[str]) -> LeverData:
        """The data of ``joints`` moving the links ``moving``, as the robot holds things now
        (what follows from the model alone is kept with it: :func:`_model_levers`)."""
        fixed = _model_levers(robot.description.model, tuple(joints), tuple(moving))
        radii = link_radii(robot)
        return cls(
            fixed.frame_links, fixed.row, dict(robot.world.bodies.attachments(robot.name)),
            fixed.centre_rows, fixed.joint_rows, fixed.local_axes, fixed.prismatic,
            np.array([radii.get(link, 0.0) for link in moving], dtype=float),
            fixed.below, fixed.after, fixed.chains,
        )  # fmt: skip

    def link_rows(self, links: Sequence[str]) -> NDArray[np.intp]:
        """Per link of ``links`` (a held object: its carrier's), its row."""
        key = tuple(links)
        rows = self._rows.get(key)
        if rows is None:  # the same links are asked about at every check of a segment
            rows = np.array([self.row[self.carriers.get(link, link)] for link in links], int)
            self._rows[key] = rows
        return rows

    def speeds(
        self,
        links: Sequence[str],
        positions: FloatArray,
        joint_origins: FloatArray,
        axes: FloatArray,
        delta: FloatArray,
    ) -> FloatArray:
        """Per link of ``links``: the most [m] a point of it moves per unit of a segment
        whose joints change by ``delta``, as posed now: its frame's speed plus its angular
        speed times its radius (the joints' motions add as vectors; far tighter than the
        levers' magnitudes summed, which no sweep of the kitchen ever needed)."""
        rows = self.link_rows(links)
        masks = self._masks.get(rows.tobytes())
        if masks is None:
            below = self.below[rows]
            masks = self._masks[rows.tobytes()] = (
                (below & ~self.prismatic).astype(float), (below & self.prismatic).astype(float)
            )  # fmt: skip
        turning, sliding = masks
        moves = delta[:, None] * axes  # (joints, 3)
        spin = turning @ moves  # (links, 3) each link's angular velocity
        centres = positions[self.centre_rows[rows]]
        # sum over revolute j of moves_j x (c - o_j) = spin x c - sum of moves_j x o_j
        linear = cross(spin, centres) - turning @ cross(moves, joint_origins) + sliding @ moves
        speed = np.sqrt((linear * linear).sum(axis=1))
        return np.asarray(speed + np.sqrt((spin * spin).sum(axis=1)) * self.radii[rows])

    def levers(
        self,
        links: Sequence[str],
        positions: FloatArray,
        joint_origins: FloatArray,
        axes: FloatArray,
    ) -> FloatArray:
        """Per link of ``links`` (a held object: its carrier's row), per joint: the lever
        [m per unit change]; ``positions`` (frame links, 3) are the frames' origins,
        ``joint_origins`` and ``axes`` (joints, 3) the joints' (any one frame for all)."""
        rows = self.link_rows(links)
        centres = positions[self.centre_rows[rows]]  # (links, 3)
        arms = cross(centres[:, None, :] - joint_origins[None, :, :], axes[None, :, :])
        levers = np.sqrt((arms * arms).sum(axis=2)) + self.radii[rows][:, None]
        levers[:, self.prismatic] = 1.0
        levers[~self.below[rows]] = 0.0
        return levers


@dataclass(frozen=True)
class _ModelLevers:
    """What :class:`LeverData` takes from the model alone (see its fields)."""

    frame_links: tuple[str, ...]
    row: dict[str, int]
    centre_rows: NDArray[np.intp]
    joint_rows: NDArray[np.intp]
    local_axes: FloatArray
    prismatic: NDArray[np.bool_]
    below: NDArray[np.bool_]
    after: NDArray[np.bool_]
    chains: FloatArray


def _model_levers(
    model: RobotModel, joints: tuple[str, ...], moving: tuple[str, ...]
) -> _ModelLevers:
    """The rows, axes, masks and chain lengths of ``joints`` moving ``moving``: they follow
    from the model (never changed) and the two names' tuples, so they are kept with it per
    tuples (every motion's checker asks; the arrays are only read)."""
    kept = model.derived(_lever_tables)
    found = kept.get((joints, moving))
    if found is None:
        found = kept.setdefault((joints, moving), _worked_out(model, joints, moving))
    return found


def _lever_tables(model: RobotModel) -> dict[tuple[tuple[str, ...], tuple[str, ...]], _ModelLevers]:
    return {}


def _worked_out(
    model: RobotModel, joints: tuple[str, ...], moving: tuple[str, ...]
) -> _ModelLevers:
    children = [model.joints[j].child for j in joints]
    frame_links = tuple(dict.fromkeys([*moving, *children]))
    at = {link: k for k, link in enumerate(frame_links)}
    tree = model.derived(_tree)
    chains = [_chains(tree, child) for child in children]  # per joint: link -> length
    arrays = (
        np.array([at[link] for link in moving], dtype=np.intp),
        np.array([at[c] for c in children], dtype=np.intp),
        np.array([model.joints[j].axis for j in joints], dtype=float).reshape(-1, 3),
        np.array([model.joints[j].type == "prismatic" for j in joints], dtype=bool),
        np.array(
            [[link in found for found in chains] for link in moving], dtype=bool
        ).reshape(len(moving), len(joints)),
        np.array(
            [[c in found and c != model.joints[j].child for c in children]
             for j, found in zip(joints, chains, strict=True)],
            dtype=bool,
        ).reshape(len(joints), len(joints)),
        np.array(
            [[found.get(link, 0.0) for found in chains] for link in moving], dtype=float
        ).reshape(len(moving), len(joints)),
    )  # fmt: skip
    for array in arrays:
        array.flags.writeable = False  # shared by every checker of these joints
    return _ModelLevers(frame_links, {link: k for k, link in enumerate(moving)}, *arrays)


def cross(a: FloatArray, b: FloatArray) -> FloatArray:
    """The cross product over the last axis (3), broadcast; numpy's own is slower for
    the small arrays a check makes."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack((a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0), axis=-1)


def links_below(robot: RobotHandle, joints: Sequence[str]) -> tuple[str, ...]:
    """The links some joint of ``joints`` moves (those below it, or below a joint that
    mimics it), in the world's link order."""
    world = robot.world
    model = robot.description.model
    tree = model.derived(_tree)
    todo = [model.joints[m].child for j in joints for m, _, _ in mimic_family(model, j)]
    below = set(todo)
    while todo:
        for child, _ in tree.get(todo.pop(), ()):
            if child not in below:
                below.add(child)
                todo.append(child)
    return tuple(link for link in world.link_names(robot.name) if link in below)


_Tree = dict[str, list[tuple[str, float]]]  # per link: its children, the joint offset [m] to each


def _tree(model: RobotModel) -> _Tree:
    """The model's links as a tree (kept with it: ``RobotModel.derived``)."""
    children: _Tree = {}
    for joint in model.joints.values():
        offset = float(np.sqrt(np.square(joint.origin.position).sum()))
        children.setdefault(joint.parent, []).append((joint.child, offset))
    return children


def _chains(tree: _Tree, link: str) -> dict[str, float]:
    """Per link at or below ``link``: the rigid lengths [m] from ``link``'s frame to its."""
    found = {link: 0.0}
    todo = [link]
    while todo:
        parent = todo.pop()
        for child, offset in tree.get(parent, ()):
            if child not in found:
                found[child] = found[parent] + offset
                todo.append(child)
    return found

"""The (moving part, obstacle piece) pairs a clearance check tests, and the test itself.

Made once per checker: every part the judge asks about (a moving link's convex pieces,
a held object's) against every obstacle piece the rules check and the part can come
within reach of for some values of the planned joints. Per check, the parts' balls give
a lower bound on each pair's distance against the pieces' map-aligned boxes, and coal
computes distances nearest bound first, per part label only until a bound cannot beat the
distance found (a few coal calls per check).
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin
from numpy.typing import NDArray

from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.obstacle_shapes import ObstacleShapes, StackedShapes
from robocram.motion.robot_geometry import Part

# [m] a check's pairs are those that can be near while no part's ball moves this far
FOCUS = 0.1


@dataclass(frozen=True)
class PairTable:
    """Pairs as arrays: per pair its part, label and the obstacle piece's box."""

    part: NDArray[np.intp]  # per pair: the part
    label: NDArray[np.intp]  # per pair: its part's label, numbered
    piece: NDArray[np.intp]  # per pair: the obstacle piece
    centres: FloatArray  # (pairs, 3) the piece's box centre in map
    halves: FloatArray  # (pairs, 3) its half extents
    radii: FloatArray  # (pairs,) the part's ball radius

    def subset(self, rows: NDArray[np.intp]) -> PairTable:
        """The pairs at ``rows``."""
        return PairTable(
            self.part[rows], self.label[rows], self.piece[rows], self.centres[rows],
            self.halves[rows], self.radii[rows],
        )  # fmt: skip

    def bounds(self, centres: FloatArray, slack: float) -> FloatArray:
        """Per pair: a lower bound [m] on its distance less ``slack``, with the parts'
        ball centres at ``centres``."""
        lower = box_distances(centres[self.part], self.centres, self.halves)
        lower -= self.radii + slack
        return lower

    def box_bounds(self, centres: FloatArray, halves: FloatArray, slack: float) -> FloatArray:
        """Per pair: the tighter of the ball's bound and that of the part's map-aligned
        box (``halves`` per part, about the same centre)."""
        points = centres[self.part]
        boxes = box_distances(points, self.centres, self.halves + halves[self.part])
        balls = box_distances(points, self.centres, self.halves) - self.radii
        return np.maximum(boxes, balls) - slack


@dataclass
class _Focus:
    """The pairs that can be near while no part's ball has moved :data:`FOCUS` from
    ``centres``: a check walks a segment in small steps, so most checks reuse it."""

    centres: FloatArray  # (parts, 3) where the balls were when it was made
    table: PairTable


@dataclass
class ClearancePairs:
    """The parts, every pair they are tested in, and the focus of the last checks."""

    parts: tuple[Part, ...]
    part_row: NDArray[np.intp]  # per part: the row of its joint in the placements
    part_centres: FloatArray  # (parts, 3) ball centres in their joint's frame
    part_axes: FloatArray  # (parts, 3, 3) their boxes' axes in their joint's frame
    part_halves: FloatArray  # (parts, 3) their boxes' half extents
    names: tuple[str, ...]  # the labels by number
    table: PairTable
    geometries: tuple[coal.CollisionGeometry, ...]  # per piece: its geometry
    placements: tuple[pin.SE3, ...]  # per piece: its placement in map
    _focus: _Focus | None = None

    @classmethod
    def of(
        cls,
        parts: list[Part],
        rows: dict[int, int],
        balls: tuple[FloatArray, FloatArray],
        shapes: StackedShapes,
        rules: PairRules,
        within: float,
    ) -> ClearancePairs:
        """The pairs the rules check whose part's ball (``balls``: centres and radii in
        map, where it can be at all) comes within ``within`` [m] of the piece's box;
        ``rows`` gives each pinocchio joint's row in the placements of a check."""
        owner, centres, halves = shapes.owner, shapes.centres, shapes.halves
        lower = box_distances(balls[0][:, None, :], centres[None], halves[None])
        near = lower - balls[1][:, None] < within
        near &= rules.matrix(parts, shapes.shapes, near, owner)[:, owner]
        if rules.allowed_pairs:  # start contacts the motion may keep
            for m, piece in zip(*np.nonzero(near), strict=True):
                near[m, piece] = (parts[m].label, shapes.labels[piece]) not in rules.allowed_pairs
        part, piece = np.nonzero(near)
        numbers = {label: k for k, label in enumerate(dict.fromkeys(p.label for p in parts))}
        part_label = np.array([numbers[p.label] for p in parts], dtype=np.intp)
        geometries, placements = shapes.geometries, shapes.placements
        radii = np.array([p.radius for p in parts], dtype=float).reshape(-1)
        table = PairTable(
            part.astype(np.intp), part_label[part].astype(np.intp), piece.astype(np.intp),
            centres[piece], halves[piece], radii[part],
        )  # fmt: skip
        return cls(
            tuple(parts),
            np.array([rows[p.joint] for p in parts], dtype=np.intp),
            _stack([p.centre[None, :] for p in parts]),
            np.array([p.axes for p in parts], dtype=float).reshape(-1, 3, 3),
            _stack([p.halves[None, :] for p in parts]),
            tuple(numbers),
            table,
            geometries,
            placements,
        )

    def gaps(self, frames: FloatArray, slack: float, reach: float) -> dict[str, float]:
        """Per label nearer than ``reach``: its least distance [m] less ``slack``.

        ``frames`` (rows, 4, 4) are the joints' placements in map now.
        """
        if not len(self.table.part):
            return {}
        rotations, origins = frames[self.part_row, :3, :3], frames[self.part_row, :3, 3]
        centres = np.einsum("mij,mj->mi", rotations, self.part_centres) + origins
        table = self._focused(centres, slack, reach).table
        halves = np.einsum("mij,mj->mi", np.abs(rotations @ self.part_axes), self.part_halves)
        lower = table.box_bounds(centres, halves, slack)
        near = np.flatnonzero(lower < reach)
        if not near.size:
            return {}
        labels = table.label[near]
        near = near[np.lexsort((lower[near], labels))]
        labels = table.label[near]
        ends = [*np.flatnonzero(labels[1:] != labels[:-1]).tolist(), len(near) - 1]
        order, bounds = near.tolist(), lower[near].tolist()
        request, result = coal.DistanceRequest(), coal.DistanceResult()
        gaps: dict[str, float] = {}
        placed: dict[int, pin.SE3] = {}  # per part: its placement now
        start = 0
        for end in ends:
            best = reach
            for at in range(start, end + 1):
                if bounds[at] >= best:
                    break  # the label's other pairs are farther still
                k = order[at]
                m, piece = int(table.part[k]), int(table.piece[k])
                part = self.parts[m]
                pose = placed.get(m)
                if pose is None:
                    pose = placed[m] = pin.SE3(frames[self.part_row[m]]) * part.placement
                result.clear()  # a result keeps the least distance of all its calls
                found = coal.distance(
                    part.geometry, pose, self.geometries[piece], self.placements[piece],
                    request, result,
                )  # fmt: skip
                best = min(best, found - slack)
            if best < reach:
                gaps[self.names[int(labels[start])]] = best
            start = end + 1
        return gaps

    def _focused(self, centres: FloatArray, slack: float, reach: float) -> _Focus:
        """The focus for balls at ``centres``: the last one unless a ball has moved
        :data:`FOCUS` since (a pair left out was farther than the reach plus that)."""
        focus = self._focus
        if focus is not None:
            moved = centres - focus.centres
            if float((moved * moved).sum(axis=1).max()) < FOCUS * FOCUS:
                return focus
        rows = np.flatnonzero(self.table.bounds(centres, slack) < reach + FOCUS)
        focus = self._focus = _Focus(centres, self.table.subset(rows))
        return focus


@dataclass(frozen=True)
class PairRules:
    """Which (part label, obstacle) pairs count, as the judge decides them."""

    rules: AllowedContacts
    held: frozenset[str]  # labels of held objects: only start contacts are allowed them
    allowed_pairs: Collection[LinkPair]  # (label, obstacle piece label) the motion starts with

    def matrix(
        self,
        parts: list[Part],
        shapes: Sequence[ObstacleShapes],
        near: NDArray[np.bool_],
        owner: NDArray[np.intp],
    ) -> NDArray[np.bool_]:
        """``[part, object]``: whether the rules check them; asked once per label and
        object, and only where some piece of the object is ``near`` the part."""
        checked = np.zeros((len(parts), len(shapes)), dtype=bool)
        rows, pieces = np.nonzero(near)
        checked[rows, owner[pieces]] = True  # first: which objects each part comes near
        asked: dict[tuple[str, int], bool] = {}
        for m, k in zip(*np.nonzero(checked), strict=True):
            label = parts[m].label
            answer = asked.get((label, k))
            if answer is None:
                obj = shapes[k].obj
                answer = label in self.held or not self.rules.allows(
                    label, Other(obj.name, obj.type)
                )
                asked[(label, k)] = answer
            checked[m, k] = answer
        return checked


def box_distances(points: FloatArray, centres: FloatArray, halves: FloatArray) -> FloatArray:
    """The distance [m] from each point to each map-aligned box (0 inside), broadcast."""
    outside = np.abs(points - centres) - halves
    np.maximum(outside, 0.0, out=outside)
    outside *= outside
    return np.asarray(np.sqrt(outside.sum(axis=-1)), dtype=float)


def _stack(arrays: list[FloatArray]) -> FloatArray:
    return np.concatenate(arrays) if arrays else np.zeros((0, 3))

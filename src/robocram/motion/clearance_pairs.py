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
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.obstacle_shapes import ObstacleShapes, StackedShapes
from robocram.motion.robot_geometry import Part
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import coal
    import pinocchio as pin
else:
    coal = LazyLibrary("coal")
    pin = LazyLibrary("pinocchio")

# [m] a check's pairs are those that can be near while no part's ball moves this far
FOCUS = 0.1


@dataclass(frozen=True)
class PairTable:
    """Pairs as arrays, coordinates first (one row per axis: a check's arithmetic runs on
    contiguous rows): per pair its part, label and obstacle piece, the piece's box."""

    ints: NDArray[np.intp]  # (3, pairs): the part, its label (numbered), the piece
    floats: FloatArray  # (7, pairs): the piece's box centre in map, its half extents,
    # the part's ball radius

    @property
    def size(self) -> int:
        """How many pairs."""
        return int(self.ints.shape[1])

    def subset(self, rows: NDArray[np.intp]) -> PairTable:
        """The pairs at ``rows``."""
        return PairTable(self.ints[:, rows], self.floats[:, rows])

    def bounds(self, centres: FloatArray, slack: float) -> FloatArray:
        """Per pair: a lower bound [m] on its distance less ``slack``, with the parts'
        ball centres at ``centres`` (3, parts)."""
        outside = np.abs(centres.take(self.ints[0], axis=1) - self.floats[:3])
        outside -= self.floats[3:6]
        np.maximum(outside, 0.0, out=outside)
        outside *= outside
        lower = np.sqrt(outside[0] + outside[1] + outside[2])
        lower -= self.floats[6]
        lower -= slack
        return lower

    def box_bounds(self, centres: FloatArray, halves: FloatArray, slack: float) -> FloatArray:
        """Per pair: the tighter of the ball's bound and that of the part's map-aligned
        box (``halves`` (3, parts), about the same centre), less ``slack``."""
        part = self.ints[0]
        ball = np.abs(centres.take(part, axis=1) - self.floats[:3])
        ball -= self.floats[3:6]
        box = ball - halves.take(part, axis=1)
        np.maximum(ball, 0.0, out=ball)
        np.maximum(box, 0.0, out=box)
        ball *= ball
        box *= box
        lower = np.sqrt(ball[0] + ball[1] + ball[2])
        lower -= self.floats[6]
        np.maximum(lower, np.sqrt(box[0] + box[1] + box[2]), out=lower)
        lower -= slack
        return lower


@dataclass(frozen=True)
class PartArrays:
    """Parts as the arrays a checker's pairs read, kept per set of parts (a stand's
    checkers ask about the same links: building them per checker cost a third of its
    pairs)."""

    parts: tuple[Part, ...]
    names: tuple[str, ...]  # the labels by number, as they first come in ``parts``
    labels: NDArray[np.intp]  # per part: its label's number
    radii: FloatArray  # (parts,) [m] the parts' ball radii
    boxes: FloatArray  # (parts, 4, 4) as ``ClearancePairs.part_boxes``

    @classmethod
    def of(cls, parts: Sequence[Part]) -> PartArrays:
        """The arrays of ``parts``."""
        numbers = {label: k for k, label in enumerate(dict.fromkeys(p.label for p in parts))}
        labels = np.array([numbers[p.label] for p in parts], dtype=np.intp)
        radii = np.array([p.radius for p in parts], dtype=float).reshape(-1)
        boxes = np.zeros((len(parts), 4, 4))
        boxes[:, 3, 3] = 1.0
        if parts:
            axes = np.array([p.axes for p in parts], dtype=float)
            boxes[:, :3, :3] = axes * np.array([p.halves for p in parts])[:, None, :]
            boxes[:, :3, 3] = np.array([p.centre for p in parts], dtype=float)
        return cls(tuple(parts), tuple(numbers), labels, radii, boxes)


@dataclass
class _Focus:
    """The pairs that can be near while no part's ball has moved :data:`FOCUS` from
    ``centres``: a check walks a segment in small steps, so most checks reuse it."""

    centres: FloatArray  # (3, parts) where the balls were when it was made
    table: PairTable


@dataclass
class ClearancePairs:
    """The parts, every pair they are tested in, and the focus of the last checks."""

    parts: tuple[Part, ...]
    part_row: NDArray[np.intp]  # per part: the row of its joint in the placements
    part_boxes: FloatArray  # (parts, 4, 4) per part in its joint's frame: its box's axes
    # scaled by its half extents, and its ball's centre (a placement's last column)
    names: tuple[str, ...]  # the labels by number
    table: PairTable
    geometries: tuple[coal.CollisionGeometry, ...]  # per piece: its geometry
    placements: tuple[pin.SE3, ...]  # per piece: its placement in map
    _focus: _Focus | None = None

    @classmethod
    def of(
        cls,
        parts: PartArrays,
        rows: dict[int, int],
        balls: ReachBalls,
        shapes: StackedShapes,
        checked: NDArray[np.bool_],
        allowed_pairs: Collection[LinkPair],
        within: float,
    ) -> ClearancePairs:
        """The pairs the rules check (``checked``: ``[label, object]``, labels numbered
        as they first come in ``parts``) but the start contacts ``allowed_pairs`` (part
        label, piece label), whose part's ball comes within ``within`` [m] of the piece's
        box; ``rows`` gives each pinocchio joint's row in the placements of a check."""
        owner, centres, halves = shapes.owner, shapes.centres, shapes.halves
        part_label = parts.labels
        lower = box_distances(balls.centres[:, None, :], centres[None], halves[None])
        near = lower[balls.anchor] - balls.radii[:, None] < within  # [part, piece]
        near &= checked[part_label][:, owner]
        if allowed_pairs:  # start contacts the motion may keep
            for m, piece in zip(*np.nonzero(near), strict=True):
                near[m, piece] = (parts.parts[m].label, shapes.labels[piece]) not in allowed_pairs
        part, piece = np.nonzero(near)
        floats = np.empty((7, len(part)))
        floats[:3] = np.take(centres, piece, axis=0).T
        floats[3:6] = np.take(halves, piece, axis=0).T
        floats[6] = parts.radii[part]
        table = PairTable(
            np.array([part, part_label[part], piece], dtype=np.intp).reshape(3, -1), floats
        )
        return cls(
            parts.parts,
            np.array([rows[p.joint] for p in parts.parts], dtype=np.intp),
            parts.boxes,
            parts.names,
            table,
            shapes.geometries,
            shapes.placements,
        )

    def gaps(self, frames: FloatArray, slack: float, reach: float) -> dict[str, float]:
        """Per label nearer than ``reach``: its least distance [m] less ``slack``.

        ``frames`` (rows, 4, 4) are the joints' placements in map now.
        """
        return self.near(frames, slack, reach).gaps()

    def near(self, frames: FloatArray, slack: float, reach: float) -> NearPairs:
        """The pairs whose bound is below ``reach`` with the joints placed at ``frames``
        (rows, 4, 4, in map), per label: coal measures a label's only when asked."""
        if not self.table.size:
            return NearPairs(self, frames, slack, reach, [], [])
        boxes = frames[self.part_row] @ self.part_boxes  # the parts' boxes in map
        centres = boxes[:, :3, 3].T
        table = self._focused(centres, slack, reach).table
        if not table.size:
            return NearPairs(self, frames, slack, reach, [], [])
        halves = np.abs(boxes[:, :3, :3]).sum(axis=2).T  # three terms: summed in order
        lower = table.box_bounds(centres, halves, slack)
        near = (lower < reach).nonzero()[0]
        if not near.size:
            return NearPairs(self, frames, slack, reach, [], [])
        ints = table.ints[:, near]
        found = lower[near]
        # by label, nearest bound first (ties: part, then piece), as tuples would sort
        order = np.lexsort((ints[2], ints[0], found, ints[1]))
        labels = ints[1, order]
        starts = np.flatnonzero(labels[1:] != labels[:-1]) + 1
        firsts = [0, *starts.tolist()]
        runs = _Runs(found[order].tolist(), ints[0, order].tolist(), ints[2, order].tolist(),
                     [*firsts[1:], len(order)])  # fmt: skip
        return NearPairs(
            self, frames, slack, reach, labels[firsts].tolist(), [runs.bounds[k] for k in firsts],
            runs, firsts,
        )  # fmt: skip

    def _focused(self, centres: FloatArray, slack: float, reach: float) -> _Focus:
        """The focus for balls at ``centres`` (3, parts): the last one unless a ball has
        moved :data:`FOCUS` since (a pair left out was farther than the reach plus that)."""
        focus = self._focus
        if focus is not None:
            moved = centres - focus.centres
            moved *= moved
            if float((moved[0] + moved[1] + moved[2]).max()) < FOCUS * FOCUS:
                return focus
        rows = (self.table.bounds(centres, slack) < reach + FOCUS).nonzero()[0]
        focus = self._focus = _Focus(centres, self.table.subset(rows))
        return focus


class NearPairs:
    """A check's near pairs per label (labels in number order), each label's least bound
    first; :meth:`gap` asks coal for one label's least distance, nearest bound first, only
    until a bound cannot beat the least found (a few coal calls per check)."""

    def __init__(
        self,
        pairs: ClearancePairs,
        frames: FloatArray,
        slack: float,
        reach: float,
        labels: list[int],
        bounds: list[float],
        runs: _Runs | None = None,
        firsts: list[int] | None = None,
    ) -> None:
        self.names = [pairs.names[label] for label in labels]  # the near labels' names
        self.bounds = bounds  # per near label: a lower bound [m] on its gap
        self._pairs = pairs
        self._frames = frames
        self._slack = slack
        self._reach = reach
        self._runs = runs  # the near pairs by label, each label's least bound first
        self._firsts = firsts or []  # per near label: where its run starts in ``runs``
        self._placed: dict[int, pin.SE3] = {}  # per part: its placement now
        self._query: tuple[coal.DistanceRequest, coal.DistanceResult] | None = None
        self._gaps: dict[int, float] = {}  # per label measured to the reach: its gap

    def gap(self, k: int, below: float | None = None) -> float:
        """Near label ``k``'s least distance [m] less the slack; the reach (or ``below``,
        if given) if it is farther.

        A gap measured to the reach is kept: asked again (a walk comes back to a
        configuration, a contact check follows a clearance), it answers at once, the same
        to the bit (below the reach, the least of the label's pairs nearer than ``below``
        is its gap, when its gap is nearer than that)."""
        kept = self._gaps.get(k)
        if kept is not None and (below is None or below <= self._reach):
            return kept if below is None or kept < below else below
        best = self._measure(k, below)
        if below is None:
            self._gaps[k] = best
        return best

    def _measure(self, k: int, below: float | None) -> float:
        """:meth:`gap` from coal: the label's pairs nearest bound first, while a bound is
        below the least distance found."""
        if self._query is None:
            self._query = (coal.DistanceRequest(), coal.DistanceResult())
        request, result = self._query
        distance, pairs, placed = coal.distance, self._pairs, self._placed
        geometries, placements, parts = pairs.geometries, pairs.placements, pairs.parts
        best = self._reach if below is None else below
        runs = self._runs
        if runs is None:
            return best
        bounds, part_of, piece_of = runs.bounds, runs.parts, runs.pieces
        for row in range(self._firsts[k], runs.ends[k]):
            if bounds[row] >= best:
                break  # the label's other pairs are farther still
            m, piece = part_of[row], piece_of[row]
            pose = placed.get(m)
            if pose is None:
                pose = placed[m] = pin.SE3(self._frames[pairs.part_row[m]]) * parts[m].placement
            result.clear()  # a result keeps the least distance of all its calls
            found = (
                distance(
                    parts[m].geometry, pose, geometries[piece], placements[piece], request, result
                )
                - self._slack
            )
            if found < best:
                best = found
        return best

    def least(self) -> float:
        """The least gap of every label (the reach if none is nearer): the minimum of
        :meth:`gaps`, to the bit, measuring labels nearest bound first and only while a
        bound is below the least gap found."""
        bounds = self.bounds
        best = self._reach
        for k in sorted(range(len(bounds)), key=bounds.__getitem__):
            if bounds[k] >= best:
                break
            best = min(best, self.gap(k, best))
        return best

    def gaps(self) -> dict[str, float]:
        """Per label nearer than the reach: its least distance [m] less the slack."""
        gaps = {}
        for k, name in enumerate(self.names):
            found = self.gap(k)
            if found < self._reach:
                gaps[name] = found
        return gaps


@dataclass(frozen=True)
class _Runs:
    """A check's near pairs sorted by label, then bound: per row its bound, part and
    piece (lists: :meth:`NearPairs.gap` reads single values), and per label where its
    rows end."""

    bounds: list[float]
    parts: list[int]
    pieces: list[int]
    ends: list[int]


@dataclass(frozen=True)
class ReachBalls:
    """Per part, a ball in map it stays in for any values of the planned joints: about
    one of a few anchors (the topmost planned joint above it)."""

    centres: FloatArray  # (anchors, 3) [m]
    anchor: NDArray[np.intp]  # per part: its anchor
    radii: FloatArray  # per part [m]


@dataclass(frozen=True)
class PairRules:
    """Which (part label, obstacle) pairs count, as the judge decides them."""

    rules: AllowedContacts
    held: frozenset[str]  # labels of held objects: only start contacts are allowed them

    def matrix(self, labels: Sequence[str], shapes: Sequence[ObstacleShapes]) -> NDArray[np.bool_]:
        """``[label, object]``: whether the rules check them."""
        return np.array(
            [
                [label in self.held or not self.rules.allows(label, Other(s.obj.name, s.obj.type))
                 for s in shapes]
                for label in labels
            ],
            dtype=bool,
        ).reshape(len(labels), len(shapes))  # fmt: skip


def box_distances(points: FloatArray, centres: FloatArray, halves: FloatArray) -> FloatArray:
    """The distance [m] from each point to each map-aligned box (0 inside), broadcast."""
    outside = np.abs(points - centres) - halves
    np.maximum(outside, 0.0, out=outside)
    outside *= outside
    return np.asarray(np.sqrt(outside.sum(axis=-1)), dtype=float)

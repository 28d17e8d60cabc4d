"""Dense checks of straight joint-space segments, as a planner and a failure need them.

``segment_free`` answers fast: it checks the interior configurations in van der Corput
order (the middle first, then the quarters...), so a blocked segment is usually found
after a few checks. ``first_collision`` walks from the start and reports where the first
collision is and what collides, for the failure a plan sees.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass

import numpy as np

from robocram.motion.configuration_checker import (
    ClearanceChecker,
    ConfigurationChecker,
    LabelGaps,
    LeverChecker,
    LinkPair,
    can_tell_clearance,
    can_tell_levers,
    can_tell_near,
    posed,
)
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.travel_bound import TravelBound

LOCAL_LEVERS_FROM = 1.0  # [m] of rigid travel bound from which steps use local levers


@dataclass
class CheckCounter:
    """Configurations checked so far: a planner's budget is counted in them."""

    checks: int = 0


def interior(n: int) -> Iterator[int]:
    """Indices 1..n-1, each once, the middle first, then the middles of the halves..."""
    spans = deque([(0, n)])
    while spans:
        low, high = spans.popleft()
        middle = (low + high) // 2
        if low < middle < high:
            yield middle
            spans.append((low, middle))
            spans.append((middle, high))


def _advance_free(
    checker: ClearanceChecker,
    qa: FloatArray,
    qb: FloatArray,
    bound: TravelBound,
    counter: CheckCounter,
    known: Mapping[str, float] | None = None,
) -> bool:
    """Conservative advancement: from each checked configuration, step as far as its
    clearance allows (no point can travel further than that), at least 1 cm of travel.

    Rigid steps take each link's travel over the whole segment: the rigid bound, or,
    when the first check's step would not end the walk, the least of it and the bound
    from the start's levers (:func:`start_travel`: a small hand step's joints partly
    undo each other, which the rigid levers' sum cannot see; ``known``: what it gave
    for this segment, the robot standing at ``qa`` as it does now)."""
    travel = bound.travel(qa, qb)  # [m] the most any point moves from qa to qb
    if travel <= 0.0:
        return True
    # the least step: the dense check's spacing on the rigid bound (``bound.steps``, as
    # :func:`first_collision` walks), kept when the travel is tightened, so a walk near a
    # contact is never coarser than that check (a tighter travel would stretch it)
    least = bound.max_link_travel / travel
    local = (  # reading levers costs a sixth of a check: worth it on long sweeps only
        _LocalSteps.of(checker, qa, qb)
        if travel > LOCAL_LEVERS_FROM and not bound.mimicked and can_tell_levers(checker)
        else None
    )
    tighten = local is None and not bound.mimicked and can_tell_levers(checker)
    by_link: dict[str, float] = {}  # [m] per link: the most a point of it moves from qa to qb
    reach = checker.reach
    nearby = can_tell_near(checker)
    s = 0.0
    while True:
        q = qa + (qb - qa) * s
        counter.checks += 1
        if nearby:  # only the labels that can limit a step are measured
            near = checker.near(q)  # type: ignore[attr-defined]
            if local is not None:
                step, touching = local.bounded_step(near, reach, bound.max_link_travel)
            else:  # rigid steps
                step, touching = _near_step(near, reach, travel, by_link, bound, qa, qb)
                if tighten and max(step, least) < 1.0:
                    tighten = False  # posed at qa: its levers bound the whole segment
                    travel = _start_travel(checker, qa, qb, bound, by_link, known)
                    if travel <= 0.0:
                        return not touching or checker.is_free(q)  # nothing that collides moves
                    step, touching = _near_step(near, reach, travel, by_link, bound, qa, qb)
            if touching and not checker.is_free(q):
                return False  # the contact check decides, as everywhere
            s += max(step, least)
            if s >= 1.0:
                return True
            continue
        gaps = checker.clearances(q)
        if min(gaps.values(), default=1.0) <= 0.0 and not checker.is_free(q):
            return False  # the contact check decides, as everywhere
        if local is not None:
            step = local.step(gaps, reach, bound.max_link_travel)
        else:
            step = _gaps_step(gaps, reach, travel, by_link, bound, qa, qb)
            if tighten and max(step, least) < 1.0:
                tighten = False  # posed at qa: its levers bound the whole segment
                travel = _start_travel(checker, qa, qb, bound, by_link, known)
                if travel <= 0.0:
                    return True  # nothing that can collide moves
                step = _gaps_step(gaps, reach, travel, by_link, bound, qa, qb)
        s += max(step, least)
        if s >= 1.0:
            return True


def _near_step(
    near: LabelGaps,
    reach: float,
    travel: float,
    by_link: dict[str, float],
    bound: TravelBound,
    qa: FloatArray,
    qb: FloatArray,
) -> tuple[float, bool]:
    """:func:`rigid_step` with each link's travel from ``by_link`` (the rigid bound where
    it has none)."""
    return rigid_step(
        near, reach, reach / travel, lambda link: _link_travel(by_link, bound, link, qa, qb)
    )


def _gaps_step(
    gaps: dict[str, float],
    reach: float,
    travel: float,
    by_link: dict[str, float],
    bound: TravelBound,
    qa: FloatArray,
    qb: FloatArray,
) -> float:
    """The rigid step from every near link's gap over its travel (``by_link``, the rigid
    bound where it has none); links not named are clear by the reach."""
    step = reach / travel
    for link, gap in gaps.items():
        moved = _link_travel(by_link, bound, link, qa, qb)
        if moved > 0.0:
            step = min(step, gap / moved)
    return step


def start_travel(
    checker: LeverChecker,
    qa: FloatArray,
    qb: FloatArray,
    bound: TravelBound,
    by_link: dict[str, float] | None = None,
) -> float:
    """The most [m] a point of a link that can collide (or of what it holds) moves on the
    straight segment ``qa`` -> ``qb``, with ``checker`` posed at ``qa``; per link (kept
    in ``by_link``) the least of two upper bounds of its travel: the rigid one
    (``bound.link_travel``) and ``V + G / 2`` from the start's levers.

    Why the second is one: a point of the link moves at most ``V(s)`` per unit of the
    walk at fraction ``s`` (its frame's speed plus its angular speed times its radius,
    the joints' motions added as vectors), and ``V(s) <= V(0) + G s`` along the whole
    segment (:class:`_LocalSteps`), so its path is at most ``V(0) + G / 2`` long. Not for
    joints with mimic followers (the levers do not see them)."""
    kept = {} if by_link is None else by_link
    links = checker.lever_links()
    if not links:
        return 0.0
    speeds = checker.link_speeds(links, qb - qa)
    ends = (speeds + _LocalSteps.of(checker, qa, qb).turn / 2).tolist()
    most = 0.0
    for link, end in zip(links, ends, strict=True):
        found = kept[link] = min(bound.link_travel(link, qa, qb), end)
        most = max(most, found)
    return most


def _start_travel(
    checker: ClearanceChecker,
    qa: FloatArray,
    qb: FloatArray,
    bound: TravelBound,
    by_link: dict[str, float],
    known: Mapping[str, float] | None,
) -> float:
    """:func:`start_travel` into ``by_link``, or, ``known`` (its per-link travels for
    this segment and pose, worked out by the caller), the same from those."""
    if known is None:
        return start_travel(checker, qa, qb, bound, by_link)  # type: ignore[arg-type]
    by_link.update(known)
    most = 0.0
    for found in known.values():  # as start_travel takes its largest
        most = max(most, found)
    return most


def _link_travel(
    by_link: dict[str, float], bound: TravelBound, link: str, qa: FloatArray, qb: FloatArray
) -> float:
    """``bound.link_travel(link, qa, qb)``, kept in ``by_link`` (a walk asks per check)."""
    found = by_link.get(link)
    if found is None:
        found = by_link[link] = bound.link_travel(link, qa, qb)
    return found


def rigid_step(
    near: LabelGaps, reach: float, first: float, travel_of: Callable[[str], float]
) -> tuple[float, bool]:
    """The step of a walk on rigid levers: the least of ``first`` and, per label nearer
    than ``reach`` that travels (``travel_of`` it > 0 [m] per unit of the walk), its gap
    over that travel; the same to the bit as from every label's gap, measuring only the
    labels whose bound can make it smaller (a label's gap is at least its bound), nearest
    first. And whether a label touches (a gap <= 0: the contact check must decide)."""
    exact: dict[int, float] = {}
    touching = False
    for k, lower in enumerate(near.bounds):
        if lower <= 0.0:
            exact[k] = near.gap(k)
            touching = touching or exact[k] <= 0.0
    hopeful = []
    for k, name in enumerate(near.names):
        travel = travel_of(name)
        if travel > 0.0:
            hopeful.append((near.bounds[k] / travel, k, travel))
    step = first
    for lowest, k, travel in sorted(hopeful):
        if lowest >= step:
            break  # no label left can make the step smaller
        gap = exact[k] if k in exact else near.gap(k)
        if gap < reach:  # farther labels are clear by the reach, as ``first`` says
            step = min(step, gap / travel)
    return step, touching


@dataclass
class _LocalSteps:
    """Steps from the frames of the configuration checked last (far tighter than the
    rigid ones): over a step ``ds`` no point of a link moves more than ``V ds + G ds^2 /
    2``. ``V`` (the link's speed bound) is its frame's speed plus its angular speed times
    its radius ``r``, the joints' motions added as vectors; ``G`` bounds how fast ``V`` can
    change along the segment. Per revolute joint j moving the link by ``|dq_j|``: its axis
    turns with the revolute joints above it (``W_j``, their summed ``|dq|``), which moves
    the frame's lever arm (at most ``c_j``, the rigid lengths from j's origin to the frame)
    by ``W_j c_j``; the frame moves relative to j's origin by ``W_j c_j`` plus what j and
    the joints below it do (``D_j``: their ``|dq|`` times their own ``c``, 1 for prismatic
    ones); and the angular speed changes by at most ``W_j``, the radius term by ``W_j r``.
    So ``G = sum_j |dq_j| (2 W_j c_j + D_j + W_j r)`` over revolute j, plus ``|dq_j| W_j``
    per prismatic joint j (its direction turns)."""

    checker: LeverChecker
    links: tuple[str, ...]
    delta: FloatArray  # qb - qa per joint
    turn: FloatArray  # per link: G
    index: dict[str, int]  # per link: its position in ``links``
    grow: list[float]  # per link: G / 2, as floats

    @classmethod
    def of(cls, checker: LeverChecker, qa: FloatArray, qb: FloatArray) -> _LocalSteps:
        links = checker.lever_links()
        delta = qb - qa
        dq = np.abs(delta)
        data = checker.lever_data()
        rows = data.link_rows(links)
        below = data.below[rows].astype(float)  # (links, joints)
        chains = data.chains[rows]  # (links, joints) [m] c: joint origin to link frame
        radii = data.radii[rows][:, None]
        revolute = ~data.prismatic
        after = checker.joints_after().astype(float)  # (joints, joints): k below i
        spin = after.T @ (dq * revolute)  # per joint: how fast its axis can turn (W)
        lever = np.where(revolute, chains, 1.0) * below  # [m per unit] of the frame
        down = (lever * dq) @ (np.eye(len(dq)) + after).T  # [l, j]: D, joint j and below
        turn = (
            (((2.0 * chains + radii) * spin + down) * revolute + spin * data.prismatic) * below @ dq
        )
        index = {link: k for k, link in enumerate(links)}
        return cls(checker, links, delta, turn, index, (turn / 2).tolist())

    def step(self, gaps: dict[str, float], reach: float, least: float = 0.0) -> float:
        """The largest fraction of the segment no link can cross its clearance (or
        ``least`` [m] > 0, the dense check's travel between checks) in; links not named in
        ``gaps`` are clear by ``reach``."""
        if not self.links:
            return 1.0
        speed = self.checker.link_speeds(self.links, self.delta)
        gap = np.full(len(self.links), max(reach, least))
        for link, clearance in gaps.items():
            k = self.index.get(link)
            if k is not None:
                gap[k] = max(clearance, least)
        return float(_quadratic_step(speed, self.turn / 2, gap).min())

    def bounded_step(self, near: LabelGaps, reach: float, least: float = 0.0) -> tuple[float, bool]:
        """:meth:`step`, the same to the bit, measuring only the labels that can limit it,
        and whether a label touches (a gap <= 0: the contact check must decide).

        A label's bound is at most its gap, so the step its bound allows is at most the
        one its gap allows: labels are measured in the order of their bounds' steps until
        that step is no smaller than the least step found. Labels whose bound is <= 0 are
        always measured: they may touch. A check has a handful of labels, so the steps
        are worked out on floats (the same operations as :func:`_quadratic_step`).
        """
        exact: dict[int, float] = {}
        touching = False
        for k, lower in enumerate(near.bounds):
            if lower <= 0.0:
                exact[k] = near.gap(k)
                touching = touching or exact[k] <= 0.0
        if not self.links:
            return 1.0, touching
        speeds = self.checker.link_speeds(self.links, self.delta)
        speed = speeds.tolist()
        grow = self.grow
        rows = {
            k: row for k, name in enumerate(near.names) if (row := self.index.get(name)) is not None
        }
        best = _least_free_step(speeds, self.turn, max(reach, least), list(rows.values()))
        hopeful = sorted(
            (_step_of(speed[row], grow[row], max(near.bounds[k], least)), k, row)
            for k, row in rows.items()
        )
        for lowest, k, row in hopeful:
            if lowest >= best:
                break  # no label left can make the step smaller
            gap = exact[k] if k in exact else near.gap(k)
            best = min(best, _step_of(speed[row], grow[row], max(gap, least)))
        return best, touching


def _least_free_step(speed: FloatArray, turn: FloatArray, free: float, taken: list[int]) -> float:
    """The least :func:`_step_of` of the links not ``taken`` (rows), each clear by ``free``
    [m], on arrays: the same operations on the same values (the same bits) at a
    fraction of a call per link."""
    if taken:
        keep = np.ones(len(speed), dtype=bool)
        keep[taken] = False
        speed, turn = speed[keep], turn[keep]
    if not len(speed):
        return math.inf
    denominator = speed + np.sqrt(speed * speed + 4.0 * (turn / 2) * free)
    steps = np.full(len(speed), math.inf)
    np.divide(2.0 * free, denominator, out=steps, where=denominator > 0.0)
    return float(steps.min())


def _step_of(speed: float, grow: float, gap: float) -> float:
    """:func:`_quadratic_step` of one link, on floats (the same operations, the same bits)."""
    denominator = speed + math.sqrt(speed * speed + 4.0 * grow * gap)
    return 2.0 * gap / denominator if denominator > 0.0 else math.inf


def _quadratic_step(speed: FloatArray, grow: FloatArray, gap: FloatArray) -> FloatArray:
    """Per link: the ``ds`` at which ``speed ds + grow ds^2`` reaches ``gap`` (> 0)."""
    denominator = speed + np.sqrt(speed * speed + 4.0 * grow * gap)
    steps = np.full(len(gap), np.inf)
    return np.divide(2.0 * gap, denominator, out=steps, where=denominator > 0.0)


def segment_free(
    checker: ConfigurationChecker,
    qa: FloatArray,
    qb: FloatArray,
    bound: TravelBound,
    counter: CheckCounter,
    known: Mapping[str, float] | None = None,
) -> bool:
    """Whether every checked configuration strictly between ``qa`` and ``qb`` is free.

    The ends are not checked: a planner checks its states once, on their own. A checker
    that can tell its clearance is walked by conservative advancement instead; ``known``:
    :func:`start_travel`'s per-link travels of this segment, worked out by the caller
    with the robot standing at ``qa`` as it does now (the walk does not work them out
    again).
    """
    qa, qb = np.asarray(qa, dtype=float), np.asarray(qb, dtype=float)
    with posed(checker):
        if can_tell_clearance(checker):
            return _advance_free(checker, qa, qb, bound, counter, known)
        n = bound.steps(qa, qb)
        for k in interior(n):
            counter.checks += 1
            if not checker.is_free(qa + (qb - qa) * (k / n)):
                return False
        return True


def first_collision(
    checker: ConfigurationChecker,
    qa: FloatArray,
    qb: FloatArray,
    bound: TravelBound,
    counter: CheckCounter,
) -> tuple[float, list[LinkPair]] | None:
    """The first colliding configuration from ``qa`` to ``qb`` (ends included): the
    fraction of the segment where it is and its colliding pairs; None when all is free."""
    n = bound.steps(qa, qb)
    qa, qb = np.asarray(qa, dtype=float), np.asarray(qb, dtype=float)
    with posed(checker):
        for k in range(n + 1):
            counter.checks += 1
            pairs = checker.colliding(qa + (qb - qa) * (k / n))
            if pairs:
                return k / n, pairs
    return None

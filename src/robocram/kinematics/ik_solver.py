"""IK for one arm: a reach check, then descents from the best starts until one converges.

A target beyond the arm's reach (:mod:`~robocram.kinematics.reach`) gets no descent: the
answer is a failure reporting the seed and its errors. Otherwise the
descents (:mod:`~robocram.kinematics.descent`) start from the seed and from the samples of
the start table nearest the target (:mod:`~robocram.kinematics.seed_table`), nearest
first, then from seeded random configurations. Restarts stop early when they cannot help:
after ``fruitless_descents`` descents in a row stall without lowering the best minimum by
1 %, the target is taken as out of reach of this arm (an orientation a short arm cannot
take, a limit in the way).

Budgets are counted, never timed: at most ``max_restarts + 1`` descents of at most
``max_iterations`` steps, so the same query and random seed give bit-identical answers on
an idle and on a loaded machine.
"""

from __future__ import annotations

import math
import time
from collections import Counter
from collections.abc import Callable, Collection, Iterator, Mapping
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.kinematics.arm_selection import arm_description, arm_joints, loaded
from robocram.kinematics.chain_sweep import chain_base
from robocram.kinematics.descent import Best, IKSettings, descend
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.kinematics_cache import KinematicsCache
from robocram.kinematics.reach import ReachBound
from robocram.kinematics.robot_kinematics import pose_to_se3, robot_kinematics
from robocram.kinematics.seed_table import ROTATION_WEIGHT, SeedTable, random_configurations
from robocram.robots import RobotDescription, RobotModel
from robocram.robots.lazy_library import LazyLibrary
from robocram.tf import Pose, PoseStamped

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

LinkPair = tuple[str, str]
CollisionCheck = Callable[[dict[str, float]], bool | Collection[LinkPair]]
"""Called with a candidate's joint values; returns True, or the colliding ``(robot link,
other)`` pairs, when that configuration collides (False or empty when it is free)."""

TABLE_SIZE = 20_000  # sampled configurations in an arm's start table
_DEFAULT = IKSettings()


class IKSolver:
    """IK for the tool frame of one arm of a description (optionally moving the torso).

    Build it once and query it many times; :meth:`cached` shares solvers between callers.
    Its start table comes from ``cache`` (by default the one the model keeps).
    """

    def __init__(
        self,
        description: RobotDescription,
        arm: str,
        use_torso: bool = False,
        frame: str | None = None,
        table_size: int = TABLE_SIZE,
        *,
        cache: KinematicsCache | None = None,
    ) -> None:
        desc, model = loaded(description)
        self.cache = cache or KinematicsCache.of(model)
        self.description = desc
        self.arm = arm
        self.use_torso = use_torso
        joints = arm_joints(desc, arm, use_torso)
        self.frame = frame or arm_description(desc, arm).tool_frame
        self.chain = self._chain(model, joints)
        self.reach = ReachBound.of(self.chain)
        self._table_size = table_size
        self._table: SeedTable | None = None
        finite = np.isfinite(self.chain.lower) & np.isfinite(self.chain.upper)
        self._middle = (
            np.where(finite, self.chain.lower, 0.0) + np.where(finite, self.chain.upper, 0.0)
        ) / 2

    def _chain(self, model: RobotModel, joints: tuple[str, ...]) -> ArmChain:
        """The chain IK moves: ``joints`` of ``model`` up to ``self.frame``."""
        return ArmChain(robot_kinematics(model), joints, self.frame)

    @classmethod
    def cached(
        cls,
        description: RobotDescription,
        arm: str,
        use_torso: bool = False,
        frame: str | None = None,
        *,
        cache: KinematicsCache | None = None,
    ) -> IKSolver:
        """The solver for these arguments, built on first use and kept in ``cache`` (by
        default the one the model keeps)."""
        desc, model = loaded(description)
        cache = cache or KinematicsCache.of(model)
        key = (cls, model, arm, use_torso, frame)
        solver = cache.solvers.get(key)
        if isinstance(solver, cls) and solver.description.arms == desc.arms:
            return solver
        built = cls(desc, arm, use_torso, frame, cache=cache)
        cache.solvers.put(key, built)
        return built

    @property
    def variables(self) -> tuple[str, ...]:
        """The joints IK sets (mimic joints replaced by their masters)."""
        return self.chain.variables

    @property
    def table(self) -> SeedTable:
        """The start table, sampled on first use (tens of milliseconds)."""
        if self._table is None:
            self._table = self.cache.seed_table(self.chain, self._table_size, self.reach.radius)
        return self._table

    def start(self, seed: Mapping[str, float]) -> FloatArray:
        """Start configuration: the seed's values, else mid-range (0 for continuous joints)."""
        middle = self._middle.tolist()
        x = np.array([seed.get(v, middle[k]) for k, v in enumerate(self.chain.variables)], float)
        return np.minimum(np.maximum(x, self.chain.lower), self.chain.upper)

    def locate(
        self,
        target: Pose | PoseStamped,
        seed: Mapping[str, float],
        start: FloatArray | None = None,
        b: FloatArray | None = None,
    ) -> tuple[pin.SE3, pin.SE3, float]:
        """The target in the root link and in the chain base (placed by the seed's FK),
        and the pose distance [m] of the seed's tool from it, as the start table measures.

        ``start`` and ``b`` are the seed's variables and offsets, if already known.
        """
        in_root = pose_to_se3(self.chain.kin.pose_in_root(target, seed))
        start = self.start(seed) if start is None else start
        b = self.chain.offsets(seed) if b is None else b
        tip = self.chain.tip_pose(start, b)
        base = chain_base(self.chain)
        in_base = base.actInv(in_root)
        return in_root, in_base, _pose_distance(base.actInv(tip), in_base)

    def reachable(self, target: Pose | PoseStamped, seed: Mapping[str, float]) -> bool:
        """False when ``target`` is certainly beyond reach; True says only "maybe"."""
        return not self.reach.excludes(self.locate(target, seed)[1], 0.0)

    def solve(
        self,
        target: Pose | PoseStamped,
        seed: Mapping[str, float] | None = None,
        settings: IKSettings | None = None,
        collision_check: CollisionCheck | None = None,
        random_seed: int = 0,
        stop_check: Callable[[], None] | None = None,
    ) -> IKResult:
        """Joint values putting the tip frame at ``target`` (see :func:`solve_ik`)."""
        t0 = time.perf_counter()
        s = settings or _DEFAULT
        seed = seed or {}
        b = self.chain.offsets(seed)
        reference = self.start(seed)
        target_se3, in_base, seed_distance = self.locate(target, seed, reference, b)
        best = Best(reference)
        descents = iterations = fruitless = 0
        hits = _Hits()
        for x in self._starts(reference, in_base, seed_distance, s, random_seed):
            if descents > s.max_restarts:
                break
            if stop_check is not None:
                stop_check()
            descents += 1
            before = best.cost
            run = descend(self.chain, x, target_se3, b, s, best)
            iterations += run.iterations
            if run.converged:
                values = self.chain.joint_positions(self.chain.wrap_continuous(run.x, reference))
                hit = collision_check(values) if collision_check is not None else False
                if not hit:
                    return self._result(True, values, best, iterations, descents, hits, t0)
                hits.add(hit)
            elif run.stalled:
                fruitless = fruitless + 1 if run.minimum > before * 0.99 else 1
                if fruitless >= s.fruitless_descents:
                    break
        if descents == 0:  # beyond reach: report the seed
            descend(self.chain, reference, target_se3, b, replace(s, max_iterations=1), best)
        values = self.chain.joint_positions(self.chain.wrap_continuous(best.x, reference))
        result = self._result(False, values, best, iterations, descents, hits, t0)
        return replace(result, beyond_reach=max(self.reach.pose_outside(in_base), 0.0))

    def _starts(
        self,
        reference: FloatArray,
        in_base: pin.SE3,
        seed_distance: float,
        s: IKSettings,
        random_seed: int,
    ) -> Iterator[FloatArray]:
        """Start configurations: seed and nearest table samples, nearest first, then random.

        None beyond the reach bound: no descent can get there.
        """
        if self.reach.excludes(in_base, s.position_tolerance, s.orientation_tolerance):
            return
        near, distance = self.table.nearest(in_base, s.table_starts)
        yield from self._with_seed(near, distance, reference, seed_distance, random_seed)

    def _with_seed(
        self,
        starts: FloatArray,
        costs: FloatArray,
        reference: FloatArray,
        seed_distance: float,
        random_seed: int,
    ) -> Iterator[FloatArray]:
        """``starts`` (sorted by ``costs``) with the seed among them by its own distance,
        then seeded random configurations without end."""
        ahead = int(np.searchsorted(costs, seed_distance))
        yield from starts[:ahead]
        yield reference
        yield from starts[ahead:]
        rng = np.random.default_rng(random_seed)
        while True:
            yield from random_configurations(self.chain, rng, 16, reference)

    def _result(
        self,
        success: bool,
        values: dict[str, float],
        best: Best,
        iterations: int,
        descents: int,
        hits: _Hits,
        t0: float,
    ) -> IKResult:
        return IKResult(
            success=success,
            joint_positions=values,
            position_error=best.position_error,
            orientation_error=best.orientation_error,
            iterations=iterations,
            restarts=max(descents - 1, 0),
            elapsed=time.perf_counter() - t0,
            rejected_in_collision=hits.rejected,
            colliding_pairs=tuple(pair for pair, _ in hits.pairs.most_common()),
        )


class _Hits:
    """What the collision check refused: how many solutions, and which pairs how often."""

    def __init__(self) -> None:
        self.rejected = 0
        self.pairs: Counter[LinkPair] = Counter()

    def add(self, hit: bool | Collection[LinkPair]) -> None:
        self.rejected += 1
        if not isinstance(hit, bool):
            self.pairs.update(hit)


def _pose_distance(a: pin.SE3, b: pin.SE3) -> float:
    """Pose distance [m] between two poses, as the start table measures it."""
    shift = a.translation - b.translation
    turn = ROTATION_WEIGHT * (a.rotation - b.rotation).ravel()
    return math.sqrt(float(shift @ shift) + float(turn @ turn))

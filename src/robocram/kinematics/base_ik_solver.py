"""IK that moves the base too: the arm chain behind planar virtual joints x, y, yaw.

The variables are the base's (:mod:`~robocram.kinematics.planar_base`) followed by the
arm's. Descents start where a small base move brings a configuration of the arm's own
start table onto the target: for every sample, the planar move that best lays its tool
pose on the target (:mod:`~robocram.kinematics.planar_fit`), scored by what that move
cannot fix (height, tilt) plus a cost on the move itself, so small base motions come
first; before any of it, the arm alone tries without moving the base. Budgets are
counted as in :class:`~robocram.kinematics.IKSolver` (the two searches' counts add up).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import replace
from typing import TYPE_CHECKING

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.kinematics.arm_selection import loaded
from robocram.kinematics.descent import IKSettings
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import CollisionCheck, IKSolver
from robocram.kinematics.kinematics_cache import KinematicsCache
from robocram.kinematics.planar_base import (
    BaseMotion,
    PlanarBase,
    for_robot,
    split_base_motion,
)
from robocram.kinematics.planar_fit import planar_fits
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import RobotDescription, RobotModel
from robocram.robots.lazy_library import LazyLibrary
from robocram.tf import Pose, PoseStamped

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

PLANAR_STARTS = 32  # fitted table samples tried before random configurations
STILL_RESTARTS = 7  # restarts of the arm alone before the base may move (8 descents)
STILL_ITERATIONS = 20  # steps per descent of the arm alone (a near miss creeps for long)


class BaseIKSolver(IKSolver):
    """IK for one arm's tool frame that may also move the base within ``base``'s travel.

    Targets are in the root link where the robot stands now; results carry the base's
    move in ``IKResult.base_motion`` and the robot's joints in ``joint_positions``.
    A collision check gets the virtual base joints (``base.joints``) among the values;
    :func:`~robocram.kinematics.planar_base.split_base_motion` separates them. The base
    drives as the description says: a differential one never slides sideways.
    """

    def __init__(
        self,
        description: RobotDescription,
        arm: str,
        use_torso: bool = False,
        frame: str | None = None,
        base: PlanarBase | None = None,
        *,
        cache: KinematicsCache | None = None,
    ) -> None:
        desc = description
        self.base = for_robot(desc, base or PlanarBase())
        super().__init__(description, arm, use_torso, frame, cache=cache)
        self.arm_solver = IKSolver.cached(self.description, arm, use_torso, frame, cache=cache)

    def _chain(self, model: RobotModel, joints: tuple[str, ...]) -> ArmChain:
        extended = robot_kinematics(self.cache.planar_model(model, self.base))
        return ArmChain(extended, (*self.base.joints, *joints), self.frame)

    @classmethod
    def cached(
        cls,
        description: RobotDescription,
        arm: str,
        use_torso: bool = False,
        frame: str | None = None,
        base: PlanarBase | None = None,
        *,
        cache: KinematicsCache | None = None,
    ) -> BaseIKSolver:
        """The solver for these arguments, built on first use and kept in ``cache`` (by
        default the one the model keeps)."""
        desc, model = loaded(description)
        cache = cache or KinematicsCache.of(model)
        base = for_robot(desc, base or PlanarBase())
        key = (cls, model, arm, use_torso, frame, base)
        solver = cache.solvers.get(key)
        if isinstance(solver, cls) and solver.description.arms == desc.arms:
            return solver
        built = cls(desc, arm, use_torso, frame, base, cache=cache)
        cache.solvers.put(key, built)
        return built

    def solve(
        self,
        target: Pose | PoseStamped,
        seed: Mapping[str, float] | None = None,
        settings: IKSettings | None = None,
        collision_check: CollisionCheck | None = None,
        random_seed: int = 0,
        stop_check: Callable[[], None] | None = None,
    ) -> IKResult:
        """The arm alone first, briefly (no base motion is the smallest); else arm and base."""
        s = settings or IKSettings()
        quick = replace(
            s,
            max_restarts=min(s.max_restarts, STILL_RESTARTS),
            max_iterations=min(s.max_iterations, STILL_ITERATIONS),
        )
        still = self.arm_solver.solve(target, seed, quick, collision_check, random_seed, stop_check)
        if still.success:
            return replace(still, base_motion=BaseMotion())
        moving = super().solve(target, seed, s, collision_check, random_seed, stop_check)
        joints, motion = split_base_motion(moving.joint_positions)
        return replace(
            moving,
            joint_positions=joints,
            base_motion=motion,
            colliding_pairs=tuple(dict.fromkeys(moving.colliding_pairs + still.colliding_pairs)),
            beyond_reach=still.beyond_reach,  # how far the base must move: the arm's figure
            iterations=still.iterations + moving.iterations,
            restarts=still.restarts + moving.restarts + (1 if still.iterations else 0),
            elapsed=still.elapsed + moving.elapsed,
            rejected_in_collision=still.rejected_in_collision + moving.rejected_in_collision,
        )

    def _starts(
        self,
        reference: FloatArray,
        in_base: pin.SE3,
        seed_distance: float,
        s: IKSettings,
        random_seed: int,
    ) -> Iterator[FloatArray]:
        """Fitted table samples, least base motion and misfit first, the seed among them
        by its own misfit; then seeded random configurations."""
        if self.reach.excludes(in_base, s.position_tolerance, s.orientation_tolerance):
            return
        # the arm table's frame: the parent of the arm's first variable, at the seed (the
        # last FK of the chain, made by ``locate``), in the virtual origin = the root link
        arm_base = self.chain.data.oMi[self.arm_solver.chain.first_row + len(self.base.joints)]
        fits = planar_fits(self.arm_solver.table, arm_base, in_base, self.base, PLANAR_STARTS)
        yield from self._with_seed(fits.starts, fits.cost, reference, seed_distance, random_seed)

"""What IK builds and keeps for reuse, bounded, on an object its caller owns.

An IK solver (its chain, reach bound and start table) takes tens of milliseconds to build
and is then asked thousands of times. :class:`KinematicsCache` keeps solvers, start tables
and the models extended by a planar base, each in a bounded least-recently-used map.

No module holds one. By default a robot model keeps its own (:meth:`KinematicsCache.of`,
stored with :meth:`~robocram.robots.RobotModel.derived`), which lives and dies with the
model. A caller that loads the same robot many times (a batch worker, a test session) may
pass one cache to every query: start tables depend only on a chain's geometry, so models
of equal geometry then sample them once. Results never depend on the cache: tables are
sampled by a fixed seed, so a solver built twice answers bit for bit the same.
"""

from __future__ import annotations

from robocram.kinematics.arm_chain import ArmChain
from robocram.kinematics.planar_base import PlanarBase, with_planar_base
from robocram.kinematics.seed_table import SeedTable, geometry_key
from robocram.logic.lru import LRUCache
from robocram.robots import RobotModel

SOLVERS_KEPT = 32  # solvers: arms x torso x frame x base of the models a cache serves
TABLES_KEPT = 16  # start tables of different chains (a few MB each)
PLANAR_MODELS_KEPT = 4  # models extended by a planar base (one per travel)


class KinematicsCache:
    """Solvers, start tables and planar-base models, each map bounded.

    Solvers are stored as plain objects and checked by their class where they are read
    (:meth:`~robocram.kinematics.IKSolver.cached`): this module sits below the solvers.
    """

    def __init__(
        self,
        solvers: int = SOLVERS_KEPT,
        tables: int = TABLES_KEPT,
        planar_models: int = PLANAR_MODELS_KEPT,
    ) -> None:
        self.solvers: LRUCache[tuple[object, ...], object] = LRUCache(solvers)
        self.tables: LRUCache[tuple[object, ...], SeedTable] = LRUCache(tables)
        self.planar_models: LRUCache[tuple[RobotModel, PlanarBase], RobotModel] = LRUCache(
            planar_models
        )

    @classmethod
    def of(cls, model: RobotModel) -> KinematicsCache:
        """The cache ``model`` keeps, made on first use."""
        return model.derived(_kept_with_model)

    def seed_table(self, chain: ArmChain, size: int, reach: float) -> SeedTable:
        """The start table of ``chain``, shared by every chain of the same geometry."""
        key = (geometry_key(chain), size, reach)
        return self.tables.get_or_build(key, lambda: SeedTable(chain, size, reach))

    def planar_model(self, model: RobotModel, base: PlanarBase) -> RobotModel:
        """``model`` below the virtual planar joints of ``base``."""
        return self.planar_models.get_or_build((model, base), lambda: with_planar_base(model, base))


def _kept_with_model(model: RobotModel) -> KinematicsCache:
    """A model's own cache (the key under which :meth:`RobotModel.derived` keeps it)."""
    return KinematicsCache()

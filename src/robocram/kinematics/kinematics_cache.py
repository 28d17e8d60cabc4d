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

import threading
from collections import OrderedDict
from collections.abc import Callable
from typing import Generic, TypeVar

from robocram.kinematics.arm_chain import ArmChain
from robocram.kinematics.errors import KinematicsArgumentError
from robocram.kinematics.planar_base import PlanarBase, with_planar_base
from robocram.kinematics.seed_table import SeedTable, geometry_key
from robocram.robots import RobotModel

K = TypeVar("K")  # hashable
V = TypeVar("V")

SOLVERS_KEPT = 32  # solvers: arms x torso x frame x base of the models a cache serves
TABLES_KEPT = 16  # start tables of different chains (a few MB each)
PLANAR_MODELS_KEPT = 4  # models extended by a planar base (one per travel)


class BoundedMap(Generic[K, V]):
    """At most ``size`` entries; adding one more drops the least recently used."""

    def __init__(self, size: int) -> None:
        if size < 1:
            raise KinematicsArgumentError(
                f"a bounded map keeps at least one entry, got size={size}"
            )
        self.size = size
        self._entries: OrderedDict[K, V] = OrderedDict()
        self._lock = threading.Lock()  # plans run IK from several threads (par)

    def __len__(self) -> int:
        return len(self._entries)

    def get(self, key: K) -> V | None:
        """The value kept for ``key`` (now the most recently used), or None."""
        with self._lock:
            value = self._entries.get(key)
            if value is not None:
                self._entries.move_to_end(key)
            return value

    def put(self, key: K, value: V) -> V:
        """Keep ``value`` for ``key``, dropping the least recently used beyond ``size``."""
        with self._lock:
            self._entries[key] = value
            self._entries.move_to_end(key)
            while len(self._entries) > self.size:
                self._entries.popitem(last=False)
        return value

    def get_or_build(self, key: K, build: Callable[[], V]) -> V:
        """The value kept for ``key``, built (outside the lock) and kept if there is none."""
        found = self.get(key)
        return self.put(key, build()) if found is None else found


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
        self.solvers: BoundedMap[tuple[object, ...], object] = BoundedMap(solvers)
        self.tables: BoundedMap[tuple[object, ...], SeedTable] = BoundedMap(tables)
        self.planar_models: BoundedMap[tuple[RobotModel, PlanarBase], RobotModel] = BoundedMap(
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

"""A table of sampled arm configurations and their tool poses: where IK starts.

Damped least squares converges in a few steps from a configuration whose tool pose is
near the target, and wanders or stalls from a far one. The table holds ``size``
configurations drawn uniformly within the limits by a seeded generator (so every solve is
repeatable), with their tool poses in the chain base (:mod:`chain_sweep`). A grid on the
tool positions finds the samples around a target; the nearest of them by position and
orientation (rotation matrices, weighted by ``ROTATION_WEIGHT`` [m]) start the descents.
A table is kept on disk (:mod:`robocram.robots.disk_cache`): a new process reads it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.kinematics.chain_sweep import sweep_tip_poses
from robocram.robots.disk_cache import kept_arrays
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

ROTATION_WEIGHT = 0.1  # [m] per unit of rotation-matrix difference
TABLE_SEED = 0  # seeds the sampled configurations; fixed, so IK answers are repeatable
CELLS_ACROSS_REACH = 8  # grid cells along the arm's reach
CACHED_CELLS = 64  # neighbourhoods a table keeps gathered (a batch visits a dozen)
# the modules whose code computes a table: a change to any of them makes new tables
BUILT_BY = (__name__, "robocram.kinematics.chain_sweep", "robocram.kinematics.arm_chain")
_AROUND = np.array([(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1)])


def random_configurations(
    chain: ArmChain, rng: np.random.Generator, count: int, reference: FloatArray
) -> FloatArray:
    """``count`` uniform configurations within limits; continuous joints within pi of
    ``reference``."""
    finite = np.isfinite(chain.lower) & np.isfinite(chain.upper)
    lo = np.where(finite, chain.lower, reference - math.pi)
    hi = np.where(finite, chain.upper, reference + math.pi)
    return rng.uniform(lo, hi, size=(count, len(lo)))


def geometry_key(chain: ArmChain) -> tuple[object, ...]:
    """Everything a chain's start table depends on: equal keys, equal tables."""
    placements = [chain.model.jointPlacements[row + 1] for row in range(len(chain.path))]
    placements.append(chain.model.frames[chain.frame_id].placement)
    joints = [chain.kin.robot_model.joints[name] for name in chain.path]
    return (
        tuple((j.type, tuple(j.axis)) for j in joints),
        b"".join(m.homogeneous.tobytes() for m in placements),
        chain.a.tobytes(),
        chain.offsets({}).tobytes(),
        chain.lower.tobytes(),
        chain.upper.tobytes(),
        chain.first_row,
    )


class SeedTable:
    """Sampled configurations of a chain, found by how close their tool pose is to a target.

    Samples are sorted by grid cell, so the samples of one cell are one slice.
    """

    def __init__(self, chain: ArmChain, size: int, reach: float) -> None:
        key = repr((geometry_key(chain), size, reach))
        versions = (pin.__version__,)
        table = kept_arrays(
            "seed-tables", key, BUILT_BY, lambda: _sampled(chain, size, reach), versions
        )
        self.cell = float(table["cell"])  # [m]
        self._low, self._shape = table["low"], table["shape"]
        # typed as built (asarray copies nothing: the arrays were built as float64)
        self.configurations = np.asarray(table["configurations"], np.float64)
        self.features = np.asarray(table["features"], np.float64)
        self._keys_sorted = table["keys"]
        self._squares = np.asarray(table["squares"], np.float64)
        # cell -> the rows' configurations, features and squared features
        self._around: dict[tuple[int, int, int], _Rows] = {}

    def _keys(self, cells: np.ndarray) -> np.ndarray:
        """One integer per grid cell (cells outside the sampled box map to -1)."""
        return _cell_keys(cells, self._low, self._shape)

    def _neighbourhood(self, cell: tuple[int, int, int]) -> _Rows:
        """The samples in ``cell`` and the 26 cells around it (cached per cell, with their
        rows gathered once: a cell is asked again and again)."""
        found = self._around.get(cell)
        if found is None:
            keys = self._keys(np.array(cell) + _AROUND)
            keys = keys[keys >= 0]
            first = np.searchsorted(self._keys_sorted, keys, side="left")
            last = np.searchsorted(self._keys_sorted, keys, side="right")
            spans = [np.arange(f, t) for f, t in zip(first, last, strict=True)]
            rows = np.concatenate([np.empty(0, np.int64), *spans])
            found = _Rows(self.configurations[rows], self.features[rows], self._squares[rows])
            if len(self._around) >= CACHED_CELLS:  # a neighbourhood's copy is ~0.1 MB
                self._around.clear()
            self._around[cell] = found
        return found

    def nearest(self, target_in_base: pin.SE3, count: int) -> tuple[FloatArray, FloatArray]:
        """Up to ``count`` configurations nearest ``target_in_base``, best first, with their
        pose distances [m]; none when no sample lies within a cell of the target."""
        position = target_in_base.translation
        x, y, z = (math.floor(v / self.cell) for v in position.tolist())
        rows = self._neighbourhood((x, y, z))
        size = rows.squares.size
        if size == 0:
            return np.empty((0, self.configurations.shape[1])), np.empty(0)
        goal = np.concatenate((position, ROTATION_WEIGHT * target_in_base.rotation.ravel()))
        distance = rows.squares - 2.0 * (rows.features @ goal) + float(goal @ goal)
        if size > count:
            pick = np.argpartition(distance, count)[:count]
            pick = pick[np.argsort(distance[pick])]
        else:
            pick = np.argsort(distance)
        return rows.configurations[pick], np.sqrt(np.maximum(distance[pick], 0.0))


def _sampled(chain: ArmChain, size: int, reach: float) -> dict[str, FloatArray]:
    """A new table's arrays: ``size`` seeded samples, sorted by grid cell."""
    rng = np.random.default_rng(TABLE_SEED)
    configurations = random_configurations(chain, rng, size, np.zeros(len(chain.variables)))
    position, rotation = sweep_tip_poses(chain, configurations @ chain.a.T + chain.offsets({}))
    cell = max(reach, 1e-3) / CELLS_ACROSS_REACH  # [m]
    cells = np.floor(position / cell).astype(np.int64)
    low = cells.min(axis=0) - 1
    shape = cells.max(axis=0) - low + 2
    keys = _cell_keys(cells, low, shape)
    order = np.argsort(keys, kind="stable")
    features = np.hstack((position, ROTATION_WEIGHT * rotation.reshape(size, 9)))[order]
    return {
        "cell": np.array(cell), "low": low, "shape": shape,
        "configurations": configurations[order], "features": features, "keys": keys[order],
        "squares": np.einsum("ij,ij->i", features, features),
    }  # fmt: skip


def _cell_keys(cells: np.ndarray, low: np.ndarray, shape: np.ndarray) -> np.ndarray:
    """One integer per grid cell of the box from ``low`` of ``shape`` (outside: -1)."""
    local = cells - low
    inside = np.all((local >= 0) & (local < shape), axis=-1)
    key = (local[..., 0] * shape[1] + local[..., 1]) * shape[2] + local[..., 2]
    return np.where(inside, key, -1)


class _Rows(NamedTuple):
    """Some samples of a table: their configurations, features and squared features."""

    configurations: FloatArray
    features: FloatArray
    squares: FloatArray

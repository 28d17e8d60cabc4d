"""Reachability maps: where around its base an arm's tool gets, from sampled FK.

Built once per robot arm from the URDF: joint values (the torso's too) are drawn from a
seeded generator, batched FK places the tool, and samples whose approach axis points
down (a grasp from above) are counted in polar bins around the base: horizontal
distance, bearing and height. An arm whose tool (almost) never points down (a SCARA
arm's wrist turns about the vertical only: IAI's Kevin) grasps from the side: its level
samples are counted instead. Used inverted around a target, the map scores the base
poses from which the target falls into well-filled bins.
Maps are kept on disk (:func:`~robocram.robots.disk_cache.kept_arrays`), keyed by the
URDF's content and the code that builds them: read whole in ~0.15 ms, where the
compressed ``.npz`` they were kept in took 1-2 ms (a zip member to find and inflate).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.batch_fk import batch_frame_poses
from robocram.costmaps.grasps import approach_axis
from robocram.costmaps.lowest_point import lowest_point
from robocram.kinematics import arm_joints
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import LoadedDescription, RobotDescription, load_description
from robocram.robots.disk_cache import kept_arrays

SAMPLES = 100_000  # FK samples per arm
RADIUS_STEP = 0.05  # [m]
RADIUS_MAX = 1.6  # [m]
BEARINGS = 24  # bins over a full turn
HEIGHT_STEP = 0.05  # [m]
HEIGHT_MAX = 2.4  # [m]
MAX_TILT = math.radians(30)  # approach axis within this of straight down counts as a grasp
MIN_DOWN_SHARE = 0.001  # of the samples pointing down, below which level ones count instead
FORMAT = 5  # bump when the map's meaning changes: old cache files are then ignored
# the modules whose code computes a map: a change to any of them makes new maps
BUILT_BY = (__name__, "robocram.costmaps.batch_fk", "robocram.costmaps.grasps")


@dataclass(frozen=True, eq=False)
class ReachabilityMap:
    """Scores 0..1 in bins ``[distance, bearing, height]`` around the base of one arm."""

    robot: str
    arm: str
    scores: NDArray[np.float64]
    bottom: float = 0.0  # [m] the lowest bin's floor, base frame: below 0 for a base held up

    def score_at(self, point_in_base: tuple[float, float, float]) -> float:
        """Score of a tool position given in the robot's base frame [m]."""
        return float(self.scores_at(np.array([point_in_base]))[0])

    def radius_at(self, z: float) -> float:
        """A distance [m] from the base's z axis beyond which every score at height ``z``
        (base frame) is 0: where a costmap need not ask."""
        h = math.floor((z - self.bottom) / HEIGHT_STEP)
        if not 0 <= h < self.scores.shape[2]:
            return 0.0
        reached = np.flatnonzero(self.scores[:, :, h].any(axis=1))
        return float(reached[-1] + 1) * RADIUS_STEP if len(reached) else 0.0

    def scores_at(self, points_in_base: NDArray[np.float64]) -> NDArray[np.float64]:
        """Scores of tool positions (N x 3, base frame [m]); 0 outside the map."""
        x, y, z = points_in_base[:, 0], points_in_base[:, 1], points_in_base[:, 2]
        r = (np.hypot(x, y) / RADIUS_STEP).astype(int)
        b = ((np.arctan2(y, x) + math.pi) / (2 * math.pi) * BEARINGS).astype(int) % BEARINGS
        h = np.floor((z - self.bottom) / HEIGHT_STEP).astype(int)
        inside = (r < self.scores.shape[0]) & (h >= 0) & (h < self.scores.shape[2])
        out = np.zeros(len(points_in_base))
        out[inside] = self.scores[r[inside], b[inside], h[inside]]
        return out


def _sample_tool_points(desc: RobotDescription, arm: str, samples: int) -> NDArray[np.float64]:
    """Tool positions (N x 3, base frame) of seeded random configurations grasping from
    above (or from the side, for an arm that cannot point its tool down)."""
    kin = robot_kinematics(load_description(desc).model)
    joints = [kin.joint(name) for name in arm_joints(desc, arm, desc.torso_joint is not None)]
    rng = np.random.default_rng(0)
    values = {
        j.name: rng.uniform(-math.pi, math.pi, samples)
        if j.continuous
        else rng.uniform(j.lower, j.upper, samples)
        for j in joints
    }
    rotations, positions = batch_frame_poses(kin, desc.arms[arm].tool_frame, values)
    approach = rotations @ approach_axis(desc, arm)
    down = approach[:, 2] <= -math.cos(MAX_TILT)
    if np.count_nonzero(down) >= MIN_DOWN_SHARE * samples:
        return positions[down]
    return positions[np.abs(approach[:, 2]) <= math.sin(MAX_TILT)]


def build_reachability_map(
    robot: RobotDescription | str, arm: str, samples: int = SAMPLES
) -> ReachabilityMap:
    """Sample FK of ``arm`` into a fresh map (no cache): about a second per arm."""
    desc = load_description(robot)
    points = _sample_tool_points(desc, arm, samples)
    bottom = base_bottom(desc)
    heights = round((HEIGHT_MAX - bottom) / HEIGHT_STEP)
    shape = (round(RADIUS_MAX / RADIUS_STEP), BEARINGS, heights)
    r = np.hypot(points[:, 0], points[:, 1]) / RADIUS_STEP
    b = (np.arctan2(points[:, 1], points[:, 0]) + math.pi) / (2 * math.pi) * BEARINGS
    h = (points[:, 2] - bottom) / HEIGHT_STEP
    index = np.stack([r, b, h], axis=1).astype(int)
    keep = np.all((index >= 0) & (index < np.array(shape)), axis=1)
    counts = np.zeros(shape)
    np.add.at(counts, tuple(index[keep].T), 1.0)
    counts = _smoothed(counts)
    peak = float(counts.max())
    return ReachabilityMap(desc.name, arm, counts / peak if peak > 0 else counts, bottom)


def base_bottom(desc: RobotDescription) -> float:
    """[m] Where the map's heights start, in the base frame: 0 for a base frame on the
    floor; the robot's lowest point (a whole bin down) for a base frame held above its
    feet or wheels, whose targets lie below it: Centauro's pelvis stands 1.03 m up, over
    the counter's mug, which a map from 0 up scored 0 from every cell. A base that is
    fixed is mounted where it works, on a pedestal or a bench as often as on the floor:
    its map starts as far down as an arm reaches (:data:`RADIUS_MAX`)."""
    # a loaded description is not checked again (every map's key asks)
    loaded = desc if isinstance(desc, LoadedDescription) else load_description(desc)
    model = loaded.model
    assert model is not None
    if loaded.drive == "fixed":
        return -RADIUS_MAX
    lowest = model.derived(lowest_point)
    return (
        round(math.floor(lowest / HEIGHT_STEP) * HEIGHT_STEP, 3) if lowest < -HEIGHT_STEP else 0.0
    )


def _smoothed(counts: NDArray[np.float64]) -> NDArray[np.float64]:
    """Average each bin with its neighbours (bearing wraps around) to fill sampling gaps."""
    out = counts.copy()
    for axis in range(3):
        for step in (1, -1):
            shifted = np.roll(counts, step, axis=axis)
            if axis != 1:  # distance and height do not wrap
                edge = [slice(None)] * 3
                edge[axis] = slice(0, 1) if step == 1 else slice(-1, None)
                shifted[tuple(edge)] = 0.0
            out += 0.5 * shifted
    return out


def _cache_key(desc: RobotDescription, arm: str, samples: int) -> str:
    """All a map follows from besides code: its parameters, the arm and the URDF."""
    assert desc.model is not None
    key = f"{FORMAT}|{samples}|{RADIUS_STEP}|{BEARINGS}|{HEIGHT_STEP}|{MAX_TILT}|{arm}|"
    bottom = base_bottom(desc)
    key += f"bottom {bottom}|" if bottom else ""
    return key + desc.model.to_urdf()


@dataclass
class ReachabilityMaps:
    """The maps of one process: in memory once loaded, on disk once built.

    Attributes:
        build_seconds: time spent building maps (not loading them), for benchmarks.
    """

    samples: int = SAMPLES
    _maps: dict[tuple[int, str], tuple[object, ReachabilityMap]] = field(
        default_factory=dict, repr=False
    )
    build_seconds: float = 0.0

    def get(self, robot: RobotDescription, arm: str) -> ReachabilityMap:
        """The map of ``robot``'s ``arm``: from memory, else from disk, else built and saved."""
        key = (id(robot.model), arm)
        entry = self._maps.get(key)
        if entry is None or entry[0] is not robot.model:  # ids of dead models get reused
            assert robot.model is not None
            kept = robot.model.derived(_kept_with_model)  # a new resolver (each batch
            found = kept.get((arm, self.samples))  # variant's) reads no file, hashes no URDF
            if found is None or found.robot != robot.name:
                found = kept[(arm, self.samples)] = self._load_or_build(robot, arm)
            entry = (robot.model, found)
            self._maps[key] = entry
        return entry[1]

    def _load_or_build(self, robot: RobotDescription, arm: str) -> ReachabilityMap:
        def build() -> dict[str, NDArray[np.float64]]:
            start = time.perf_counter()
            built = build_reachability_map(robot, arm, self.samples)
            self.build_seconds += time.perf_counter() - start
            return {"scores": built.scores}

        key = _cache_key(robot, arm, self.samples)
        scores = np.asarray(kept_arrays("reachability", key, BUILT_BY, build)["scores"], float)
        return ReachabilityMap(robot.name, arm, scores, base_bottom(robot))


def _kept_with_model(model: object) -> dict[tuple[str, int], ReachabilityMap]:
    """The maps a robot model keeps (:meth:`~robocram.robots.RobotModel.derived`), by arm
    and sample count: the rest of their file's key is the model's, fixed while it lives.
    The model is parsed once per process, so each map is read once per process too."""
    return {}

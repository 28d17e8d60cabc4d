"""Reachability maps: where around its base an arm's tool gets, from sampled FK.

Built once per robot arm from the URDF: joint values (the torso's too) are drawn from a
seeded generator, FK places the tool, and samples whose approach axis points down (a
grasp from above) are counted in polar bins around the base: horizontal distance,
bearing and height. Used inverted, the map says for a target at distance ``d`` and
height ``z`` how well the arm reaches it and at which bearing the base should hold it.
Maps are cached on disk under :func:`cache_dir`, keyed by the URDF's content.
"""

from __future__ import annotations

import hashlib
import math
import os
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pinocchio as pin
from numpy.typing import NDArray

from robocram.costmaps.grasps import approach_axis
from robocram.kinematics import arm_joints
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import RobotDescription, load_description

SAMPLES = 24000  # FK samples per arm
RADIUS_STEP = 0.05  # [m]
RADIUS_MAX = 1.6  # [m]
BEARINGS = 24  # bins over a full turn
HEIGHT_STEP = 0.05  # [m]
HEIGHT_MAX = 2.4  # [m]
MAX_TILT = math.radians(45)  # approach axis within this of straight down counts as a grasp
FORMAT = 2  # bump when the map's meaning changes: old cache files are then ignored


def cache_dir() -> Path:
    """``$ROBOCRAM_CACHE_DIR``, else ``$XDG_CACHE_HOME/robocram``, else ``~/.cache/robocram``."""
    explicit = os.environ.get("ROBOCRAM_CACHE_DIR")
    if explicit:
        return Path(explicit)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "robocram"


@dataclass(frozen=True, eq=False)
class ReachabilityMap:
    """Scores 0..1 in bins ``[distance, bearing, height]`` around the base of one arm."""

    robot: str
    arm: str
    scores: NDArray[np.float64]

    def best(
        self, distance: NDArray[np.float64], height: float
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Best score and the bearing [rad] (of the target in the base) giving it, per distance."""
        r = np.clip((distance / RADIUS_STEP).astype(int), 0, self.scores.shape[0] - 1)
        h = int(np.clip(height / HEIGHT_STEP, 0, self.scores.shape[2] - 1))
        column = self.scores[:, :, h]
        best_bin = np.argmax(column, axis=1)
        bearing = (best_bin + 0.5) * (2 * math.pi / BEARINGS) - math.pi
        score = column[np.arange(column.shape[0]), best_bin]
        outside = distance >= RADIUS_MAX
        return np.where(outside, 0.0, score[r]), bearing[r]


def _sample_tool_points(desc: RobotDescription, arm: str, samples: int) -> NDArray[np.float64]:
    """Tool positions (N x 3, base frame) of seeded random configurations grasping from above.

    Runs pinocchio's FK directly on configuration vectors (mimic joints stay put: they are
    fingers, not on the way to the tool frame), some 40x faster than one query at a time.
    """
    model = desc.model
    assert model is not None  # loaded by the caller
    kin = robot_kinematics(model)
    joints = [kin.joint(name) for name in arm_joints(desc, arm, desc.torso_joint is not None)]
    lows = [-math.pi if j.continuous else j.lower for j in joints]
    highs = [math.pi if j.continuous else j.upper for j in joints]
    values = np.random.default_rng(0).uniform(lows, highs, size=(samples, len(joints)))
    axis = approach_axis(desc, arm)
    frame = kin.frame_id(desc.arms[arm].tool_frame)
    q = kin.configuration({})
    points = []
    for row in values:
        for joint, value in zip(joints, row, strict=True):
            if joint.continuous:
                q[joint.idx_q : joint.idx_q + 2] = (math.cos(value), math.sin(value))
            else:
                q[joint.idx_q] = value
        pin.framesForwardKinematics(kin.model, kin.data, q)
        tool = kin.data.oMf[frame]
        if (tool.rotation @ axis)[2] <= -math.cos(MAX_TILT):
            points.append(tool.translation.copy())
    return np.asarray(points, dtype=float).reshape(-1, 3)


def build_reachability_map(
    robot: RobotDescription | str, arm: str, samples: int = SAMPLES
) -> ReachabilityMap:
    """Sample FK of ``arm`` into a fresh map (no cache): about a second per arm."""
    desc = load_description(robot)
    points = _sample_tool_points(desc, arm, samples)
    shape = (round(RADIUS_MAX / RADIUS_STEP), BEARINGS, round(HEIGHT_MAX / HEIGHT_STEP))
    r = np.hypot(points[:, 0], points[:, 1]) / RADIUS_STEP
    b = (np.arctan2(points[:, 1], points[:, 0]) + math.pi) / (2 * math.pi) * BEARINGS
    h = points[:, 2] / HEIGHT_STEP
    index = np.stack([r, b, h], axis=1).astype(int)
    keep = np.all((index >= 0) & (index < np.array(shape)), axis=1)
    counts = np.zeros(shape)
    np.add.at(counts, tuple(index[keep].T), 1.0)
    counts = _smoothed(counts)
    peak = float(counts.max())
    return ReachabilityMap(desc.name, arm, counts / peak if peak > 0 else counts)


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


def _cache_file(desc: RobotDescription, arm: str, samples: int) -> Path:
    assert desc.model is not None
    key = f"{FORMAT}|{samples}|{RADIUS_STEP}|{BEARINGS}|{HEIGHT_STEP}|{MAX_TILT}|{arm}|"
    digest = hashlib.sha1((key + desc.model.to_urdf()).encode("utf-8")).hexdigest()[:16]
    return cache_dir() / "reachability" / f"{desc.name}-{arm}-{digest}.npz"


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
            entry = (robot.model, self._load_or_build(robot, arm))
            self._maps[key] = entry
        return entry[1]

    def _load_or_build(self, robot: RobotDescription, arm: str) -> ReachabilityMap:
        path = _cache_file(robot, arm, self.samples)
        if path.is_file():
            with np.load(path) as data:
                return ReachabilityMap(robot.name, arm, np.asarray(data["scores"], float))
        start = time.perf_counter()
        built = build_reachability_map(robot, arm, self.samples)
        self.build_seconds += time.perf_counter() - start
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".npz")
        with os.fdopen(fd, "wb") as out:
            np.savez_compressed(out, scores=built.scores)
        os.replace(tmp, path)
        return built

"""An arm's reach envelope: how far it stretches over its joint range, and which way it works.

A telescope's reach is its length extended, not at its zero (retracted): Stretch's arm
reaches about 0.7 m, not 0.21 m. And an arm need not work straight ahead of its base:
Stretch's reaches along its base's -y. The working direction is read from where the wrist
gets over seeded joint values within the limits: the far samples (at least
:data:`FAR_SHARE` of the farthest horizontal distance from the shoulder) are counted by
bearing in four quarters (ahead, left, behind, right). The arm works straight ahead (+x,
the convention every description keeps) unless fewer than :data:`MIN_AHEAD_SHARE` of them
are ahead; then towards the fullest quarter. An arm on a sideways mount that turns ahead
too (Boxy's, TALOS's, Baxter's: an eighth or more) keeps +x; Stretch's, ahead only when
retracted, works along -y.
Where the robot has a body (links no joint moves, with shapes), the far samples are counted
by the side of the body's footprint they lie beyond instead (``robots/body_clearance.py``):
an arm on the side of a long base, turning all round, works to that side, not across it.
A lift (the arm's leading vertical prismatic joints) is held at the middle of its range;
the shoulder is where the first joint after it starts.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from robocram.robots.body_clearance import beyond_body
from robocram.robots.description import ArmDescription
from robocram.robots.disk_cache import kept_arrays
from robocram.robots.model_pose import finite_limits, joint_transform, link_pose
from robocram.robots.robot_model import RobotModel
from robocram.tf import Pose

SAMPLES = 256  # seeded joint samples for the working direction
FAR_SHARE = 0.5  # of the farthest horizontal wrist distance: the samples that count
MIN_AHEAD_SHARE = 0.05  # of the far wrist samples ahead of the shoulder, else it works aside
QUARTERS = (0.0, math.pi / 2, -math.pi / 2, math.pi)  # [rad] ahead first: it wins ties
VERTICAL = 0.9  # |z| of a unit axis in the root link above which it is vertical
# the modules whose code finds the working direction (kept on disk: robots/disk_cache.py)
BUILT_BY = (
    __name__, "robocram.robots.body_clearance", "robocram.robots.link_centre",
    "robocram.robots.model_pose", "robocram.robots.mimic", "robocram.robots.robot_model",
    "robocram.tf.pose", "robocram.tf.quaternion",
)  # fmt: skip


@dataclass(frozen=True)
class ArmEnvelope:
    """An arm's reach [m] past its shoulder and its working direction in the base frame."""

    reach: float  # [m] shoulder to wrist along the chain, stretched over the joint range
    working_yaw: float  # [rad] about the base's z: 0 straight ahead (+x), -pi/2 its -y
    lift: tuple[str, ...]  # the arm's leading vertical prismatic joints (Stretch's lift)
    shoulder: tuple[float, float, float]  # [m] base frame: where the first joint after the
    # lift starts (its origin, at zero), the lift at its middle

    @property
    def working_pose(self) -> Pose:
        """The base frame turned so that its x points the arm's working direction."""
        half = self.working_yaw / 2
        return Pose(orientation=(0.0, 0.0, math.sin(half), math.cos(half)))


def _axis_z(model: RobotModel, joint: str) -> float:
    """The z of ``joint``'s unit axis in the root link, at zero."""
    spec = model.joints[joint]
    frame = link_pose(model, spec.parent) * joint_transform(spec, 0.0)
    axis = np.asarray(spec.axis, dtype=float)
    turned = (
        Pose(orientation=frame.orientation) * Pose(tuple(axis / np.linalg.norm(axis)))
    ).position
    return float(turned[2])


def lift_joints(model: RobotModel, arm: ArmDescription) -> tuple[str, ...]:
    """The arm's leading joints that slide vertically: a lift carrying it up and down."""
    lift: list[str] = []
    for name in arm.joints:
        spec = model.joints[name]
        if spec.type != "prismatic" or abs(_axis_z(model, name)) <= VERTICAL:
            break
        lift.append(name)
    return tuple(lift)


def _with_followers(model: RobotModel, arm: ArmDescription, joints: tuple[str, ...]) -> list[str]:
    """``joints`` and the chain joints that mimic one of them (a coupled telescope's), in
    chain order: each segment of the chain counts in its stretched length."""
    chain = model.chain(model.joints[joints[0]].parent, arm.end_effector_link)
    return [
        j.name
        for j in chain
        if j.name in joints or (j.mimic is not None and j.mimic.joint in joints)
    ]


def _middle(model: RobotModel, joints: tuple[str, ...]) -> dict[str, float]:
    values = {}
    for name in joints:
        limits = finite_limits(model.joints[name])
        values[name] = 0.0 if limits is None else sum(limits) / 2
    return values


def _shoulder(model: RobotModel, joint: str, values: Mapping[str, float]) -> Pose:
    """Where ``joint`` starts, in the base frame: its origin in its parent link."""
    spec = model.joints[joint]
    return link_pose(model, spec.parent, values) * spec.origin


def _stretched(
    model: RobotModel, first: str, links: list[str], values: Mapping[str, float]
) -> float:
    points = [_shoulder(model, first, values).position]
    points += [link_pose(model, link, values).position for link in links]
    return sum(math.dist(p, q) for p, q in zip(points, points[1:], strict=False))


def arm_reach(
    model: RobotModel, arm: ArmDescription, fixed: Mapping[str, float] | None = None
) -> float:
    """Shoulder-to-wrist length [m] along the chain, stretched over the joint range.

    Turning joints stay at zero (stretched out, as a chain of fixed lengths); sliding ones
    go to the limit at which the chain is longer (a telescope, extended).
    """
    lift = lift_joints(model, arm)
    rest = arm.joints[len(lift) :]
    if not rest:
        return 0.0
    links = [model.joints[j].child for j in _with_followers(model, arm, rest)]
    links.append(arm.end_effector_link)
    values = {**_middle(model, lift), **(fixed or {})}
    sliding = [j for j in rest if model.joints[j].type == "prismatic"]
    ends = []
    for pick in (0, 1):
        at_limit = {}
        for name in sliding:
            limits = finite_limits(model.joints[name])
            at_limit[name] = 0.0 if limits is None else limits[pick]
        ends.append(_stretched(model, rest[0], links, {**values, **at_limit}))
    return max(ends)


def joint_samples(model: RobotModel, joints: tuple[str, ...]) -> list[dict[str, float]]:
    """:data:`SAMPLES` seeded values of ``joints``, uniform within their limits."""
    rng = np.random.default_rng(0)
    columns = {}
    for name in joints:
        limits = finite_limits(model.joints[name]) or (-math.pi, math.pi)
        columns[name] = rng.uniform(limits[0], limits[1], SAMPLES)
    return [{n: float(c[i]) for n, c in columns.items()} for i in range(SAMPLES)]


class _Directions:
    """Working directions found for one model, by arm chain and held joints."""

    def __init__(self, model: RobotModel) -> None:
        self.model = model
        self.found: dict[tuple[object, ...], float] = {}


def working_yaw(
    model: RobotModel, arm: ArmDescription, fixed: Mapping[str, float] | None = None
) -> float:
    """The arm's working direction [rad] about the base's z (see the module docstring).

    Kept with the model: the knowledge base asks it for every world the robot enters.
    """
    key = (arm.joints, arm.end_effector_link, tuple(sorted((fixed or {}).items())))
    found = model.derived(_Directions).found
    if key not in found:  # a new process reads it from disk once computed
        kept = kept_arrays(
            "arm-directions", f"{model.to_urdf()}\n{key}", BUILT_BY,
            lambda: {"yaw": np.array(_working_yaw(model, arm, fixed))},
        )  # fmt: skip
        found[key] = float(kept["yaw"])
    return found[key]


def _working_yaw(
    model: RobotModel, arm: ArmDescription, fixed: Mapping[str, float] | None
) -> float:
    lift = lift_joints(model, arm)
    rest = arm.joints[len(lift) :]
    if not rest:
        return 0.0
    held = {**_middle(model, lift), **(fixed or {})}
    shoulder = _shoulder(model, rest[0], held).position
    wrists = np.array(
        [
            link_pose(model, arm.end_effector_link, {**held, **s}).position
            for s in joint_samples(model, rest)
        ]
    )
    offsets = wrists - shoulder
    distances = np.hypot(offsets[:, 0], offsets[:, 1])
    far = distances >= FAR_SHARE * distances.max()
    beyond = beyond_body(model, wrists[far])
    if beyond is not None and beyond.any():  # which side of the body the clear wrists are
        shares = [float(np.mean(side)) for side in beyond.T]
    else:
        bearings = np.arctan2(offsets[far, 1], offsets[far, 0])
        shares = [
            float(
                np.mean(np.abs((bearings - q + math.pi) % (2 * math.pi) - math.pi) <= math.pi / 4)
            )
            for q in QUARTERS
        ]
    if shares[0] >= MIN_AHEAD_SHARE:
        return 0.0
    return QUARTERS[int(np.argmax(shares))]


def arm_envelope(
    model: RobotModel, arm: ArmDescription, fixed: Mapping[str, float] | None = None
) -> ArmEnvelope:
    """The reach and working direction of ``arm`` (its joints set), ``fixed`` joints held."""
    lift = lift_joints(model, arm)
    first = arm.joints[len(lift)] if len(arm.joints) > len(lift) else arm.joints[-1]
    held = {**_middle(model, lift), **(fixed or {})}
    return ArmEnvelope(
        reach=arm_reach(model, arm, fixed),
        working_yaw=working_yaw(model, arm, fixed),
        lift=lift,
        shoulder=_shoulder(model, first, held).position,
    )

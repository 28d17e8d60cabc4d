"""Which pairs of a robot's own links a motion must keep apart, MoveIt's setup way.

MoveIt's setup assistant samples the robot's configurations once and writes the pairs it
need never check into the SRDF. Here the same is worked out on the projection world's own
shapes (PyBullet's hulls, what every check and the audit measure), once per robot model:
- **adjacent**: joined by one joint (fixed joints merged, links without shapes looked
  through);
- **always**: touching in every sampled configuration (:data:`SAMPLES`, seeded), as hulls
  of neighbouring covers do: they can never be apart, so their contact says nothing;
- **default**: touching where the robot rests (every arm and the neck parked, grippers
  open or closed), as MoveIt disables pairs in collision at its default pose: convex
  hulls of a folded elbow's two halves overlap where the meshes clear, and a Fetch tucked
  as its makers tuck it sinks its forearm's hull 10 mm into the torso's (the depths are
  kept: :attr:`SelfCollisionMatrix.rest_depths`). Bounding such a pair by its depth at
  rest refused a PR2 opening the fridge (its upper arm's hull sweeps the torso's deeper as
  the door pulls it back), so, as in MoveIt, it is not checked. Drafted parking poses keep
  clear of the robot (:mod:`~robocram.robots.draft.stowing`), so this only trusts poses a
  user or an SRDF gave;
- **chained**: one hangs below the other across two movable joints (an HSR's arm roll
  link and its wrist roll link, a wrist flex between): the joint limits between keep
  the real links apart, while their convex hulls, which bridge the joint, overlap when
  it flexes. Three joints apart (a PR2's forearm and its own fingers) is checked;
- **fingers**: two fingers of one gripper (``gripper_links``): they close on each other
  by design (a TALOS hand's three tips meet halfway through closing);
- **allowed**: the description's ``allowed_contacts`` name the pair (an SRDF's disabled
  pairs are drafted into them).

- **never**: never nearer than :data:`NEVER_GAP` in :data:`NEVER_SAMPLES` seeded samples
  of every joint within its limits (a PR2's laser mount and a shoulder that pans beside
  it, 3 cm apart at their nearest), as MoveIt's setup assistant finds them. Sampling
  cannot prove a pair apart; the audit (:mod:`~robocram.traces.trajectory_audit`) judges
  every pair the matrix skips as never, so a sample that missed shows up there.

Every other pair of links with shapes is checked, also within one arm (a forearm against
its own fingers). The built-in robots' matrices are stored with their descriptions
(:mod:`~robocram.motion.stored_self_collision`): a process reads them instead of sampling.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import cast

import numpy as np

from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.self_collision import adjacent_pairs
from robocram.motion.stored_self_collision import matrix_digest, read_stored
from robocram.robots import LoadedDescription, RobotModel
from robocram.world import RobotHandle

SAMPLES = 64  # configurations sampled to find pairs always in contact
SEED = 0
NEVER_SAMPLES = 1000  # configurations sampled to find pairs that never come near
NEVER_GAP = 0.01  # [m] a pair nearer than this in some sample is checked


@dataclass(frozen=True)
class SelfCollisionMatrix:
    """The checked pairs of one robot's links, and why each other pair is skipped."""

    checked: tuple[tuple[str, str], ...]
    skipped: Mapping[frozenset[str], str]  # pair -> why (adjacent, chained, never, ...)
    rest_depths: Mapping[frozenset[str], float] = field(default_factory=dict)  # [m] default

    @classmethod
    def of(cls, robot: RobotHandle) -> SelfCollisionMatrix:
        """The matrix of ``robot`` (worked out on first use, kept with its model)."""
        handle = robot.body
        desc = handle.description
        kept = desc.model.derived(_Kept).matrices
        key = _description_key(desc)
        found = kept.get(key)
        if found is None:
            digest = matrix_digest(desc, key)
            stored = read_stored(desc.name, digest)
            found = cls.from_data(stored) if stored is not None else _work_out(robot)
            kept[key] = found
        return found

    @classmethod
    def worked_out(cls, robot: RobotHandle) -> tuple[SelfCollisionMatrix, str]:
        """The matrix of ``robot`` worked out anew (nothing stored or kept is read), and
        the digest it is stored under (``tools/store_self_collision.py``)."""
        desc = robot.description
        return _work_out(robot), matrix_digest(desc, _description_key(desc))

    def to_data(self) -> dict[str, object]:
        """The matrix as JSON data (pairs in a fixed order)."""
        return {
            "checked": [list(p) for p in self.checked],
            "skipped": sorted([*sorted(p), why] for p, why in self.skipped.items()),
            "rest_depths": sorted([*sorted(p), d] for p, d in self.rest_depths.items()),
        }

    @classmethod
    def from_data(cls, data: Mapping[str, object]) -> SelfCollisionMatrix:
        """The matrix :meth:`to_data` gave."""
        checked = cast(list[list[str]], data["checked"])
        skipped = cast(list[list[str]], data["skipped"])
        depths = cast(list[tuple[str, str, float]], data["rest_depths"])
        return cls(
            tuple((str(a), str(b)) for a, b in checked),
            {frozenset((str(a), str(b))): str(why) for a, b, why in skipped},
            {frozenset((str(a), str(b))): float(d) for a, b, d in depths},
        )

    def reason(self, a: str, b: str) -> str | None:
        """Why the pair ``a``, ``b`` is not checked (None: it is)."""
        return self.skipped.get(frozenset((a, b)))


@dataclass
class _Kept:
    """The matrices worked out for a model, per description of it."""

    model: RobotModel
    matrices: dict[tuple[object, ...], SelfCollisionMatrix] = field(default_factory=dict)


def _description_key(desc: LoadedDescription) -> tuple[object, ...]:
    """What of a description, beyond its model, the matrix depends on: its allowed
    contacts, its arms' parking poses and fingers, its neck's parking and its legs' stance
    (a scene loads the description anew, the model is kept per process: the matrix is
    worked out once)."""
    arms = tuple(
        (name, tuple(sorted(arm.parking.items())), tuple(arm.gripper_joints),
         tuple(arm.gripper_links))
        for name, arm in sorted(desc.arms.items())
    )  # fmt: skip
    key = (tuple(desc.allowed_contacts), arms, tuple(sorted(desc.neck_parking.items())))
    return (*key, tuple(sorted(desc.stance.items()))) if desc.stance else key


def _work_out(robot: RobotHandle) -> SelfCollisionMatrix:
    handle = robot.body
    desc = handle.description
    names = handle.collider_names()
    links = sorted(set(names.values()))
    skipped: dict[frozenset[str], str] = {}
    for pair in adjacent_pairs(desc.model, links):
        skipped[pair] = "adjacent"
    for a, b in itertools.combinations(links, 2):
        pair = frozenset((a, b))
        if pair not in skipped and _chained(desc.model, a, b):
            skipped[pair] = "chained"
    for arm in desc.arms.values():
        fingers = sorted(set(arm.gripper_links) & set(links))
        for a, b in itertools.combinations(fingers, 2):
            skipped.setdefault(frozenset((a, b)), "fingers")
    rules = AllowedContacts.of(desc)
    for a, b in itertools.combinations(links, 2):
        pair = frozenset((a, b))
        if pair not in skipped and (
            rules.allows(a, Other(b, "robot")) or rules.allows(b, Other(a, "robot"))
        ):
            skipped[pair] = "allowed"
    candidates = [
        (a, b) for a, b in itertools.combinations(links, 2) if frozenset((a, b)) not in skipped
    ]
    for always in _always_touching(robot, candidates):
        skipped[frozenset(always)] = "always"
    left = [p for p in candidates if frozenset(p) not in skipped]
    rest_depths: dict[frozenset[str], float] = {}
    for resting, depth in _touching_at_rest(robot, left).items():
        skipped[frozenset(resting)] = "default"
        rest_depths[frozenset(resting)] = depth
    left = [p for p in candidates if frozenset(p) not in skipped]
    for never in _never_near(robot, left):
        skipped[frozenset(never)] = "never"
    checked = tuple(p for p in candidates if frozenset(p) not in skipped)
    return SelfCollisionMatrix(checked, skipped, rest_depths)


def _always_touching(
    robot: RobotHandle, candidates: list[tuple[str, str]]
) -> list[tuple[str, str]]:
    """The pairs among ``candidates`` touching in every sampled configuration: a pair
    apart in one sample is dropped, so later samples ask only the survivors."""
    world = robot.world
    model = robot.description.model
    movable = [
        j for j in world.joint_states(robot.name)
        if model.joints[j].mimic is None
    ]  # fmt: skip
    before = {j: v for j, v in world.joint_states(robot.name).items() if j in movable}
    rng = np.random.default_rng(SEED)
    survivors = list(candidates)
    try:
        for _ in range(SAMPLES):
            if not survivors:
                break
            world.set_joint_states(robot.name, _sample(model, movable, rng), carry=False)
            touching = world.contacts.self_distances(robot.name, survivors, 0.0)
            survivors = [p for k, p in enumerate(survivors) if touching[k] <= 0.0]
    finally:
        world.set_joint_states(robot.name, before, carry=False)
    return survivors


def _never_near(robot: RobotHandle, candidates: list[tuple[str, str]]) -> list[tuple[str, str]]:
    """The pairs among ``candidates`` never nearer than :data:`NEVER_GAP` in the samples
    (a pair found near once is asked no more)."""
    world = robot.world
    model = robot.description.model
    movable = [j for j in world.joint_states(robot.name) if model.joints[j].mimic is None]
    before = {j: v for j, v in world.joint_states(robot.name).items() if j in movable}
    rng = np.random.default_rng(SEED + 1)
    far = list(candidates)
    try:
        for _ in range(NEVER_SAMPLES):
            world.set_joint_states(robot.name, _sample(model, movable, rng), carry=False)
            gaps = world.contacts.self_distances(robot.name, far, NEVER_GAP)
            far = [p for p, gap in zip(far, gaps.tolist(), strict=True) if gap >= NEVER_GAP]
    finally:
        world.set_joint_states(robot.name, before, carry=False)
    return far


def _touching_at_rest(
    robot: RobotHandle, candidates: list[tuple[str, str]]
) -> dict[tuple[str, str], float]:
    """The pairs among ``candidates`` touching with every arm and the neck parked, the
    legs in their stance, the grippers closed or open, the other joints at zero (within
    their limits), each with
    its deepest penetration [m] there (>= 0)."""
    world = robot.world
    desc = robot.description
    model = desc.model
    movable = [j for j in world.joint_states(robot.name) if model.joints[j].mimic is None]
    before = {j: v for j, v in world.joint_states(robot.name).items() if j in movable}
    rest = {j: _clamped(model, j, 0.0) for j in movable}
    for arm in desc.arms.values():
        rest.update({j: v for j, v in arm.parking.items() if j in rest})
    rest.update({j: v for j, v in desc.neck_parking.items() if j in rest})
    rest.update({j: v for j, v in desc.stance.items() if j in rest})
    grippers = [j for arm in desc.arms.values() for j in arm.gripper_joints if j in rest]
    found: dict[tuple[str, str], float] = {}
    try:
        for end in ("lower", "upper"):
            values = dict(rest)
            for j in grippers:
                values[j] = _clamped(model, j, getattr(model.joints[j], end) or 0.0)
            world.set_joint_states(robot.name, values, carry=False)
            touching = world.contacts.self_distances(robot.name, candidates, 0.0)
            for pair, gap in zip(candidates, touching.tolist(), strict=True):
                if gap <= 0.0:
                    found[pair] = max(found.get(pair, 0.0), -gap)
    finally:
        world.set_joint_states(robot.name, before, carry=False)
    return {p: found[p] for p in candidates if p in found}


def _clamped(model: RobotModel, joint: str, value: float) -> float:
    spec = model.joints[joint]
    lower = -math.inf if spec.lower is None else spec.lower
    upper = math.inf if spec.upper is None else spec.upper
    return min(max(value, lower), upper)


def _chained(model: RobotModel, a: str, b: str) -> bool:
    """Whether one of ``a``, ``b`` hangs below the other across two movable joints."""
    up_a, up_b = _joints_up(model, a), _joints_up(model, b)
    lower, upper = (up_a, up_b) if len(up_a) > len(up_b) else (up_b, up_a)
    return lower[len(lower) - len(upper) :] == upper and len(lower) - len(upper) == 2


def _joints_up(model: RobotModel, link: str) -> list[str]:
    """The movable joints from ``link`` up to the root, in order."""
    found = []
    joint = model.parent_joint(link)
    while joint is not None:
        if joint.movable:
            found.append(joint.name)
        joint = model.parent_joint(joint.parent)
    return found


def _sample(model: RobotModel, joints: list[str], rng: np.random.Generator) -> dict[str, float]:
    values = {}
    for name in joints:
        joint = model.joints[name]
        lower = -math.pi if joint.lower is None else max(joint.lower, -math.pi * 2)
        upper = math.pi if joint.upper is None else min(joint.upper, math.pi * 2)
        values[name] = float(rng.uniform(lower, upper)) if upper > lower else lower
    return values

"""A stowed parking pose for a drafted arm: compact, within limits, touching nothing.

A real robot parks its arm stowed: folded close to its body, a telescope retracted, so
that the base fits where it stands at counters (Stretch's sampled pose left the gripper
sticking out, and every kitchen stand was refused as ``robot_collision_free``). Without
an SRDF naming one, the draft searches for it: the arm's joint origins and hand kept
horizontally close to the middle of the base, the hand not above the shoulder (out of
the camera's view), everything above the floor and on the arm's own side, a telescope at
its retracted limit. Candidates are checked on the collision meshes
(:class:`~robocram.robots.self_contacts.SelfContacts`).
The stowed pose replaces the sampled one (:mod:`~robocram.robots.draft.parking`) where
it touches nothing and is more compact, or where the sampled one touches and the stowed
one is about as compact (:func:`better_parking`). An arm carrying the camera parks
otherwise (:func:`looking_pose`): stowed, its camera would see the robot's own body.
Where a stowed arm hangs in a body camera's view (Centauro's elbow before its head
camera), the search is run again keeping the arm out of the view (:class:`CameraView`);
where the head pans with a waist that turns the arms too (Centauro's ``torso_yaw``), the
parked arm must touch nothing with the waist turned either way as well (``swept``).
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.draft.parking import (
    FLOOR_CLEARANCE,
    ChainPoses,
    joint_range,
    parking_pose,
    rounded_inside,
)
from robocram.robots.link_centre import link_centre
from robocram.robots.robot_model import RobotModel
from robocram.robots.self_contacts import SelfContacts
from robocram.tf import Pose

SAMPLES = 800
CANDIDATES = 200  # cheapest samples checked for contacts, in order
REFINE_ROUNDS = 4
BETTER = 0.02  # [m] closer to the base's middle than the sampled pose by this, to replace it
SLACK = 0.1  # [m] farther out than a sampled pose that touches, at most, to replace it
VERTICAL = 0.9  # |z| of a unit axis above which a sliding joint is a lift, not a telescope
NEAR = 0.05  # [m] points nearer the camera than this are its own housing, not in view


@dataclass(frozen=True)
class CameraView:
    """A camera's view in the root link: its optical frame (z forward) and fields of view
    [rad]; what lies within ``depth`` [m] in front of it, inside both, is in view."""

    pose: Pose
    horizontal_fov: float
    vertical_fov: float
    depth: float = 2.0

    def sees_any(self, points: np.ndarray) -> bool:
        """Whether any of ``points`` (N x 3, root link) lies in the view."""
        inverse = self.pose.inverse().matrix()
        local = points @ inverse[:3, :3].T + inverse[:3, 3]
        x, y, z = local[:, 0], local[:, 1], local[:, 2]
        ahead = (z > NEAR) & (z < self.depth)
        across = np.abs(np.arctan2(x, z)) < self.horizontal_fov / 2
        along = np.abs(np.arctan2(y, z)) < self.vertical_fov / 2
        return bool(np.any(ahead & across & along))


@dataclass(frozen=True)
class Stowed:
    """Arm joint values, how far [m] the arm gets from the base's middle, whether it touches."""

    values: dict[str, float]
    extent: float
    touches: bool


def _retracted(model: RobotModel, joints: Sequence[str]) -> dict[str, float]:
    """Sliding joints that are no lift, at their limit nearest zero: a telescope retracted."""
    poses = link_poses(model)
    fixed = {}
    for name in joints:
        spec = model.joints[name]
        if spec.type == "prismatic" and abs(axis_in_root(model, name, poses)[2]) <= VERTICAL:
            lower, upper = joint_range(model, name)
            fixed[name] = lower if abs(lower) <= abs(upper) else upper
    return fixed


class _Search:
    """The arm's points for a pose, their cost, and the contact check."""

    def __init__(
        self,
        model: RobotModel,
        joints: Sequence[str],
        wrist: str,
        contacts: SelfContacts,
        view: CameraView | None = None,
        swept: Sequence[Mapping[str, float]] = ({},),
    ) -> None:
        self.joints = tuple(joints)
        self.view = view
        self.swept = tuple(swept)
        self.chain = ChainPoses(model, joints, wrist)
        self.limits = [joint_range(model, j) for j in joints]
        self.fixed = _retracted(model, joints)
        self.contacts = contacts
        tree, poses = ModelTree(model), link_poses(model)
        hand = [wrist, *tree.subtree_links(wrist)]
        first = model.joints[self.joints[0]].child
        self.arm_links = frozenset((first, *tree.subtree_links(first)))
        self.hand = [
            poses[wrist].inverse() * poses[n] * Pose(link_centre(model.links[n])) for n in hand
        ]
        base = [
            (poses[n] * Pose(link_centre(model.links[n]))).position
            for n in tree.rigid_group(model.root_link)
        ]
        self.middle = np.mean(np.asarray(base)[:, :2], axis=0)
        below = set(tree.subtree_links(wrist))
        self.hand_states = _hand_states(model, [
            j.name for j in model.joints.values()
            if j.movable and j.mimic is None and j.child in below
        ])  # fmt: skip
        shoulder = (self.chain.base * self.chain.chain[0].origin).position
        self.shoulder = float(shoulder[2])
        across = shoulder[1] - self.middle[1]  # an arm on one side stays on it
        self.side = float(np.sign(across)) if abs(across) > 0.05 else 0.0

    def points(self, values: Sequence[float]) -> np.ndarray:
        poses = self.chain.poses(values)
        found = [p.position for p in poses] + [(poses[-1] * h).position for h in self.hand]
        return np.asarray(found)

    def in_view(self, values: Sequence[float]) -> bool:
        """Whether the arm at ``values`` hangs in the camera's view (its joints, the
        middles between them and its hand's shapes), where a view is given."""
        if self.view is None:
            return False
        points = self.points(values)
        chain = points[: -len(self.hand)] if self.hand else points
        middles = (chain[1:] + chain[:-1]) / 2
        return self.view.sees_any(np.vstack((points, middles)))

    def extent(self, values: Sequence[float]) -> float:
        return float(np.linalg.norm(self.points(values)[:, :2] - self.middle, axis=1).max())

    def cost(self, values: Sequence[float]) -> float:
        points = self.points(values)
        low = np.maximum(FLOOR_CLEARANCE - points[:, 2], 0.0).sum()
        hand = points[-len(self.hand) :, 2]
        high = np.maximum(hand - self.shoulder, 0.0).sum()
        spread = np.linalg.norm(points[:, :2] - self.middle, axis=1)
        crossed = np.maximum(self.side * (self.middle[1] - points[:, 1]), 0.0).sum()
        return float(spread.max() + 0.1 * spread.mean() + 2.0 * low + high + crossed)

    def touches(self, values: Sequence[float]) -> bool:
        """Whether the arm at ``values`` touches itself with the hand closed or open."""
        arm = dict(zip(self.joints, values, strict=True))
        return any(
            self.contacts.touches({**arm, **hand}, turned=above, parts=self.arm_links)
            for above in self.swept
            for hand in self.hand_states
        )

    def sample(self, rng: random.Random) -> list[float]:
        return [
            self.fixed.get(name, rng.uniform(lo, hi))
            for name, (lo, hi) in zip(self.joints, self.limits, strict=True)
        ]

    def refine(self, values: list[float]) -> list[float]:
        """Coordinate descent on the cost, each step kept only if it touches nothing."""
        best, best_cost, step = values, self.cost(values), 0.2
        for _ in range(REFINE_ROUNDS):
            for i, (lo, hi) in enumerate(self.limits):
                if self.joints[i] in self.fixed:
                    continue
                for delta in (-step, step):
                    trial = list(best)
                    trial[i] = min(max(trial[i] + delta, lo), hi)
                    cost = self.cost(trial)
                    if cost < best_cost and not self.in_view(trial) and not self.touches(trial):
                        best, best_cost = trial, cost
            step /= 2
        return best

    def judged(self, values: Sequence[float]) -> Stowed:
        named = dict(zip(self.joints, values, strict=True))
        return Stowed(named, self.extent(values), self.touches(values))


def _hand_states(model: RobotModel, joints: Sequence[str]) -> list[dict[str, float]]:
    """The hand's joints (fingers) at zero, at their lower and at their upper limits: a
    parked arm's gripper opens and closes where it is."""
    states: list[dict[str, float]] = [{}]
    for end in (0, 1):
        state = {j: joint_range(model, j)[end] for j in joints}
        if state:
            states.append(state)
    return states


def stowed_pose(
    model: RobotModel,
    joints: Sequence[str],
    wrist: str,
    contacts: SelfContacts | None = None,
    seed: int = 0,
    view: CameraView | None = None,
    swept: Sequence[Mapping[str, float]] = ({},),
) -> Stowed | None:
    """The stowed pose of the arm (see the module docstring), or None if every candidate
    touches (in any of the ``swept`` states of the joints above it) or, with a ``view``,
    hangs in it; values within limits, to 3 decimals."""
    search = _Search(model, joints, wrist, contacts or SelfContacts(model), view, swept)
    return _best(search, seed)


def parked_unclear(
    model: RobotModel,
    parking: Mapping[str, float],
    wrist: str,
    view: CameraView | None,
    swept: Sequence[Mapping[str, float]],
) -> bool:
    """Whether the arm parked at ``parking`` hangs in ``view`` or touches the robot in one
    of the ``swept`` states of the joints above it."""
    search = _Search(model, list(parking), wrist, model.derived(SelfContacts), view, swept)
    values = list(parking.values())
    return search.in_view(values) or (len(swept) > 1 and search.touches(values))


def _best(search: _Search, seed: int) -> Stowed | None:
    """The cheapest seeded sample that touches nothing, refined; None if all touch."""
    rng = random.Random(seed)
    ranked = sorted((search.sample(rng) for _ in range(SAMPLES)), key=search.cost)
    if search.view is not None:
        ranked = [values for values in ranked if not search.in_view(values)]
    for values in ranked[:CANDIDATES]:
        if not search.touches(values):
            best = search.refine(values)
            judged = search.judged(
                [rounded_inside(v, lim) for v, lim in zip(best, search.limits, strict=True)]
            )
            return None if judged.touches else judged
    return None


def judged_parking(
    model: RobotModel, parking: Mapping[str, float], wrist: str, contacts: SelfContacts
) -> Stowed:
    """How far the arm parked at ``parking`` gets from the base's middle, and if it touches."""
    search = _Search(model, list(parking), wrist, contacts)
    return search.judged(list(parking.values()))


def better_parking(stowed: Stowed | None, sampled: Stowed) -> bool:
    """Whether the stowed pose replaces the sampled one: it touches nothing and is more
    compact, or the sampled one touches and the stowed one is about as compact."""
    if stowed is None or stowed.touches:
        return False
    if sampled.touches:
        return stowed.extent <= sampled.extent + SLACK
    return stowed.extent < sampled.extent - BETTER


@dataclass(frozen=True)
class DraftedParking:
    """The parking pose a draft writes, why, and the doubt left."""

    values: dict[str, float]
    why: str
    doubt: str | None


def drafted_parking(model: RobotModel, joints: Sequence[str], wrist: str) -> DraftedParking:
    """The stowed pose where it is better than the sampled one (:func:`better_parking`),
    else the sampled one; the model keeps the meshes checked for the next arm."""
    contacts = model.derived(SelfContacts)
    sampled = judged_parking(model, parking_pose(model, joints, wrist), wrist, contacts)
    stowed = stowed_pose(model, joints, wrist, contacts)
    if stowed is not None and better_parking(stowed, sampled):
        retracted = ", the telescope retracted" if _retracted(model, joints) else ""
        was = "touching" if sampled.touches else f"{sampled.extent:.2f} m out"
        why = (
            f"stowed: within limits{retracted}, the arm within {stowed.extent:.2f} m of the "
            f"base's middle (the sampled pose: {was}), 1 cm clear of its other links (meshes)"
        )
        return DraftedParking(stowed.values, why, None)
    why = "sampled in limits (seed 0): wrist low beside the shoulder, out of view"
    doubt = "no collision check here: `robocram robot check` drives it"
    if sampled.touches:
        pairs = ", ".join("/".join(p) for p in contacts.meeting(sampled.values)[:2])
        doubt = f"its links touch ({pairs}) and no stowed pose was found: give one"
    return DraftedParking(sampled.values, why, doubt)


AHEAD = 0.25  # [m] a camera-carrying arm parks its wrist this far ahead of its shoulder
ABOVE = 0.2  # [m] and this far above it, so that the camera looks over the robot's body


class _LookingSearch(_Search):
    """A parked arm that carries the camera: wrist ahead of and above the shoulder, the
    hand hanging below the wrist (out of the camera's view), above the floor."""

    def __init__(
        self, model: RobotModel, joints: Sequence[str], wrist: str, contacts: SelfContacts
    ) -> None:
        super().__init__(model, joints, wrist, contacts)
        shoulder = (self.chain.base * self.chain.chain[0].origin).position
        self.goal = np.asarray(shoulder) + (AHEAD, 0.0, ABOVE)

    def cost(self, values: Sequence[float]) -> float:
        points = self.points(values)
        wrist = self.chain.poses(values)[-1].position
        low = np.maximum(FLOOR_CLEARANCE - points[:, 2], 0.0).sum()
        hand = np.maximum(points[-len(self.hand) :, 2] - wrist[2], 0.0).sum()
        return float(np.linalg.norm(np.subtract(wrist, self.goal)) + 2.0 * low + hand)


def looking_pose(
    model: RobotModel, joints: Sequence[str], wrist: str, seed: int = 0
) -> Stowed | None:
    """A parking pose for an arm whose wrist carries the camera (see
    :class:`_LookingSearch`), touching nothing, or None; within limits, to 3 decimals."""
    return _best(_LookingSearch(model, joints, wrist, model.derived(SelfContacts)), seed)

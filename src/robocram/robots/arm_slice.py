"""Whether an arm needs its base to reach: its reach envelope is a thin slice, or small.

Where the hand gets over seeded joint values within the limits is a cloud of points. Its
principal spreads say its shape: an arm that moves in one plane (Stretch's lift and
telescope, the HSR's arm without a shoulder pan) spreads in two directions only, so a
target off that plane is reached by moving the base, whatever the number of joints. An
arm that reaches less than :data:`SMALL_REACH` (the SO-101's) cannot cover a table's
front from one stand either. Every other earlier arm spreads in three directions
(flatness 0.53 or more; the HSR's 0.24, Stretch's 0.03).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from robocram.robots.arm_envelope import arm_reach, joint_samples
from robocram.robots.description import ArmDescription, RobotDescription
from robocram.robots.disk_cache import kept_arrays
from robocram.robots.model_pose import link_pose
from robocram.robots.robot_model import RobotModel

THIN = 0.35  # smallest over largest spread of the hand's positions: below, a thin slice
SMALL_REACH = 0.4  # [m] an arm reaching less past its shoulder is small
# the modules whose code computes the flatness (kept on disk: :mod:`~robocram.robots.disk_cache`)
BUILT_BY = (
    __name__, "robocram.robots.arm_envelope", "robocram.robots.model_pose",
    "robocram.robots.mimic", "robocram.robots.robot_model", "robocram.tf.pose",
    "robocram.tf.quaternion",
)  # fmt: skip


@dataclass(frozen=True)
class ArmSlice:
    """The shape of an arm's reach envelope."""

    flatness: float  # smallest over largest principal spread of the hand's positions
    reach: float  # [m] past the shoulder, over the joint range

    @property
    def planar(self) -> bool:
        """The hand moves in a thin slice: a planar arm."""
        return self.flatness < THIN

    @property
    def small(self) -> bool:
        """The arm reaches less than :data:`SMALL_REACH`."""
        return self.reach < SMALL_REACH

    @property
    def needs_base(self) -> bool:
        """Targets off the slice, or beyond the small reach, need the base to move."""
        return self.planar or self.small


class _Slices:
    """Envelope shapes found for one model, by arm chain."""

    def __init__(self, model: RobotModel) -> None:
        self.found: dict[tuple[object, ...], ArmSlice] = {}


def arm_slice(model: RobotModel, arm: ArmDescription) -> ArmSlice:
    """The shape of ``arm``'s envelope (its joints set), kept with the model."""
    key = (arm.joints, arm.end_effector_link)
    found = model.derived(_Slices).found
    if key not in found:
        found[key] = ArmSlice(_flatness(model, arm), arm_reach(model, arm))
    return found[key]


def _flatness(model: RobotModel, arm: ArmDescription) -> float:
    """The flatness of the hand's sampled positions, read from disk once computed."""
    joints = tuple(j for j in arm.joints if model.joints[j].mimic is None)
    if not joints:
        return 0.0
    tip = arm.end_effector_link
    key = f"{model.to_urdf()}\n{joints}\n{tip}"
    kept = kept_arrays(
        "arm-slices", key, BUILT_BY, lambda: {"flatness": np.array(_sampled(model, tip, joints))}
    )
    return float(kept["flatness"])


def _sampled(model: RobotModel, tip: str, joints: tuple[str, ...]) -> float:
    """Smallest over largest principal spread of ``tip``'s positions over seeded values."""
    points = np.array([link_pose(model, tip, s).position for s in joint_samples(model, joints)])
    spreads = np.linalg.svd(points - points.mean(axis=0), compute_uv=False)
    spreads /= math.sqrt(len(points))
    return float(spreads[2] / spreads[0]) if spreads[0] > 1e-9 else 0.0


def slice_advice(desc: RobotDescription, spec: ArmDescription, base_moved: bool) -> str | None:
    """Advice for a planar arm that missed with its base still (``base_moved`` False):
    reach with the base too; None for any other arm."""
    if base_moved or desc.model is None or not spec.joints or desc.drive == "fixed":
        return None
    shape = arm_slice(desc.model, spec)
    if not shape.planar:
        return None
    return (
        f"the {spec.name} arm moves in a thin slice (flatness {shape.flatness:.2f}): let IK "
        f"move the base too (arms[{spec.name!r}] base_in_ik=True, or move_base=True)"
    )

"""Telescopes in a URDF: prismatic joints in a row that one actuator moves together.

Stretch's arm is four prismatic joints (``joint_arm_l3`` to ``joint_arm_l0``), each
sliding its segment out of the previous one along the same axis, with the same limits;
the robot drives them with one motor. Left free, IK and projection would move them
independently, to poses the real arm cannot take. The draft couples such a row: the
first joint is the actuator, the others follow it (:class:`JointCoupling`, a ``<mimic>``
of multiplier 1 at load).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.model_additions import JointCoupling
from robocram.robots.urdf_elements import Joint

PARALLEL = 0.999  # axes' dot product above which two prismatic joints slide alike
SAME_LIMIT = 1e-6  # [m] limits closer than this are equal


@dataclass(frozen=True)
class Telescope:
    """A coupling found in the URDF and why it was drafted."""

    coupling: JointCoupling
    why: str


def _free_prismatic(tree: ModelTree, joint: Joint) -> bool:
    return joint.type == "prismatic" and joint.mimic is None and not tree.is_mimicked(joint.name)


def _next_segment(tree: ModelTree, joint: Joint, axes: dict[str, np.ndarray]) -> Joint | None:
    """The one joint sliding on from ``joint``'s segment alike, if there is exactly one."""
    alike = [
        nxt
        for nxt in tree.movable_roots(joint.child)
        if _free_prismatic(tree, nxt)
        and float(axes[nxt.name] @ axes[joint.name]) > PARALLEL
        and abs((nxt.lower or 0.0) - (joint.lower or 0.0)) < SAME_LIMIT
        and abs((nxt.upper or 0.0) - (joint.upper or 0.0)) < SAME_LIMIT
    ]
    return alike[0] if len(alike) == 1 else None


def find_telescopes(tree: ModelTree) -> list[Telescope]:
    """Rows of two or more alike prismatic joints, each on the previous one's segment."""
    model = tree.model
    poses = link_poses(model)
    sliding = [j for j in model.joints.values() if _free_prismatic(tree, j)]
    axes = {j.name: axis_in_root(model, j.name, poses) for j in sliding}
    continued: set[str] = set()
    rows: dict[str, list[Joint]] = {}
    for joint in sliding:
        row = [joint]
        nxt = _next_segment(tree, joint, axes)
        while nxt is not None:
            row.append(nxt)
            nxt = _next_segment(tree, nxt, axes)
        rows[joint.name] = row
        continued.update(j.name for j in row[1:])
    found = []
    for name, row in rows.items():
        if name in continued or len(row) < 2:
            continue
        names = [j.name for j in row]
        why = (
            f"{len(row)} prismatic joints in a row sliding along one axis with equal limits: "
            "a telescope, moved by one actuator"
        )
        found.append(Telescope(JointCoupling(names[0], tuple(names[1:])), why))
    return found

"""A pre-grasp and a lift nearer the grasp, tried after the usual ones failed.

The usual pre-grasp stands 0.1 m off the grasp along the approach (over it, for a grasp
from above or a handle's), and the lift raises the object 0.1 m. Under a wall cupboard,
a hand 0.1 m over the counter's mug raises TALOS's elbow into the cupboard's bottom
(1.40 m; its upper arm at 1.43 m), and 5 cm over or a lift of 3.5 cm do so too; 3.5 cm
over and a lift of 1.5 cm keep it clear (measured: docs/new_robot.md, zoo20). The hand
then comes in along the last part of the same approach, and the object leaves the
surface it stood on all the same. Where even that pre-grasp is out of reach, one
:data:`NEAREST_SHARE` of the way is tried: the B1's Z1, its base squared 0.65 m from the
counter's mug (the nearest its hips stand clear), holds its jaw down over the handle's
outer end (the one grasp that keeps the jaw out of the mug) 2 cm up, not 3.5 cm (7 mm
short; docs/new_robot.md, zoo24).
"""

from __future__ import annotations

from dataclasses import replace

from robocram.knowledge.grasp_predicates import ObjectGrasp
from robocram.tf import PoseStamped

NEARER_SHARE = 0.35  # of the usual pre-grasp's way off the grasp
NEAREST_SHARE = 0.2  # the last try's, after every nearer one failed
NEARER_LIFT_SHARE = 0.15  # of the usual lift's way off the grasp


def nearer_pre_grasp(
    choice: ObjectGrasp, share: float = NEARER_SHARE, lift_share: float = NEARER_LIFT_SHARE
) -> ObjectGrasp:
    """``choice`` with its pre-grasp and its lift moved to ``share`` of their way off the
    grasp (``map``), their orientations kept: a lift as high as the usual raises the
    elbow as far."""
    return replace(
        choice,
        pre_grasp=towards(choice.pre_grasp, choice.grasp_pose, share),
        lift=towards(choice.lift, choice.grasp_pose, lift_share),
    )


def towards(pose: PoseStamped, grasp: PoseStamped, share: float) -> PoseStamped:
    """``pose`` moved to ``share`` of its way off ``grasp`` (both ``map``)."""
    gx, gy, gz = grasp.position
    px, py, pz = pose.position
    nearer = (gx + share * (px - gx), gy + share * (py - gy), gz + share * (pz - gz))
    return replace(pose, position=nearer)

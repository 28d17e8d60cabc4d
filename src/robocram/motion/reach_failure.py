"""Why an arm cannot reach a pose, said so that the advice fits the robot and the cause.

The IK result says what collided (``colliding_pairs``) and how far the target lies beyond
the arm's reach (``beyond_reach``). The message names the colliding link pairs and advises
only what applies: moving the base closer only when the target is out of reach (and by how
much), the other arm only when the robot has one, letting the hand touch only when the
hand hit an object while every contact was forbidden, adding links to ``hand_links`` only
when a link below the wrist that is not listed hit the object being grasped. A planar arm
(its reach envelope a thin slice, :mod:`robocram.robots.arm_slice`) that missed without
its base is told to reach with its base (``base_in_ik``), not to turn or move the base.
"""

from __future__ import annotations

from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.kinematics import IKResult
from robocram.robots import ArmDescription, RobotDescription
from robocram.robots.arm_slice import slice_advice
from robocram.robots.model_pose import subtree_links
from robocram.tf import Pose

SHOWN_PAIRS = 4  # colliding pairs named in a message, most frequent first
POSITION_MISS = 0.01  # [m] a best configuration missing by more is off in position


def unreachable(
    desc: RobotDescription,
    arm: str,
    target: object,
    target_in_map: Pose,
    mode: str,
    result: IKResult,
) -> ManipulationPoseUnreachable:
    """The failure for ``arm`` missing ``target`` (``result`` is the failed IK answer)."""
    spec = desc.arms[arm]
    pairs = result.colliding_pairs
    text = (
        f"{desc.name}'s {arm} arm cannot reach {_position(target_in_map)} (map) with "
        f"collision mode {mode}: "
    )
    if pairs:
        shown = ", ".join(f"{link}-{other}" for link, other in pairs[:SHOWN_PAIRS])
        more = f" and {len(pairs) - SHOWN_PAIRS} more" if len(pairs) > SHOWN_PAIRS else ""
        text += (
            f"{result.rejected_in_collision} solutions rejected in collision "
            f"(robot link-object: {shown}{more})"
        )
    elif result.beyond_reach > 0:
        text += f"the target lies {result.beyond_reach:.3f} m beyond the arm's reach"
    else:
        text += (
            f"best IK configuration misses by {result.position_error:.3f} m, "
            f"{result.orientation_error:.3f} rad"
        )
    advice = _advice(desc, spec, mode, result)
    return ManipulationPoseUnreachable(
        text + ("; " + "; ".join(advice) if advice else ""),
        arm=arm,
        target=target,
        colliding_pairs=pairs or None,
        beyond_reach=result.beyond_reach or None,
    )


def _position(pose: Pose) -> str:
    return "(" + ", ".join(f"{c:.3f}" for c in pose.position) + ")"


def _within_length_advice(result: IKResult) -> str:
    """What to try when the target is within the arm's length but no pose reaches it."""
    if result.position_error > POSITION_MISS:
        return (
            f"the joint limits keep the tool {result.position_error:.3f} m off: turn or move "
            "the base so that the target lies in front of the arm"
        )
    return (
        f"the position is reachable, its orientation is {result.orientation_error:.2f} rad "
        "off: try another grasp orientation"
    )


def _advice(desc: RobotDescription, spec: ArmDescription, mode: str, result: IKResult) -> list[str]:
    advice = []
    planar = slice_advice(desc, spec, result.base_motion is not None)
    if planar is not None and (result.beyond_reach > 0 or not result.colliding_pairs):
        advice.append(planar)
    elif result.beyond_reach > 0:
        advice.append(f"move the base at least {result.beyond_reach:.3f} m closer")
    hand = set(spec.hand_links) | set(spec.gripper_links)
    hand |= {spec.end_effector_link, spec.tool_frame}
    links = {link for link, _ in result.colliding_pairs}
    if mode == "avoid_all" and links & hand:
        touched = sorted({other for link, other in result.colliding_pairs if link in hand})
        advice.append(
            f"if the hand is to touch {', '.join(touched)} (grasping), allow it with "
            "collision_mode='allow_hand'"
        )
    below = subtree_links(desc.model, spec.end_effector_link) if desc.model else ()
    unlisted = sorted((links - hand) & set(below))
    if mode == "allow_hand" and unlisted:
        advice.append(
            f"{', '.join(unlisted)} hang below the wrist but are not in the {spec.name} arm's "
            "hand_links; add them if they are part of the hand"
        )
    if links - hand - set(unlisted):
        advice.append("approach from another side, or place the base so the arm clears it")
    if result.beyond_reach <= 0 and not result.colliding_pairs:
        within = _within_length_advice(result)
        if planar is None or not within.startswith("the joint limits"):
            advice.append(within)
    others = [k for k in desc.arms if k not in (spec.name, desc.neck_arm)]
    if others and (result.beyond_reach > 0 or not result.colliding_pairs):
        advice.append(f"or use the other arm ({', '.join(others)})")
    return advice

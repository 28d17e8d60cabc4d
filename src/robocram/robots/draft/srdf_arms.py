"""Take a drafted robot's arms, parking and self-contacts from its SRDF instead of guesses.

An SRDF end effector names the link its gripper hangs on; the arm group ending there gives
the arm's joints. A named state such as "tuck" is the pose the robot's makers park it in,
better than a sampled one. ``disable_collisions`` pairs become allowed contacts: MoveIt's
setup assistant found them adjacent or never touching.
"""

from __future__ import annotations

from dataclasses import replace

from robocram.robots.description import ArmDescription, RobotDescription
from robocram.robots.draft.stowing import drafted_parking
from robocram.robots.robot_model import RobotModel
from robocram.robots.srdf import Srdf, SrdfEndEffector, SrdfGroup

PARKING_WORDS = ("stow", "tuck", "park", "home", "rest", "transport")  # preferred first


def _arm_joints(model: RobotModel, group: SrdfGroup, tip: str, torso: str | None) -> list[str]:
    """The group's movable, unmimicked joints on the path to ``tip``, base first."""
    path = model.chain(model.root_link, tip)
    return [
        j.name
        for j in path
        if j.name in group.joints and j.movable and j.mimic is None and j.name != torso
    ]


def _arm_group(
    model: RobotModel, srdf: Srdf, effector: SrdfEndEffector, torso: str | None
) -> tuple[SrdfGroup, list[str]] | None:
    """The group the end effector's arm is, with its joints: the parent group, else the
    smallest group ending at the parent link (an arm without the torso before one with)."""
    if effector.parent_group is not None:
        group = srdf.groups[effector.parent_group]
        joints = _arm_joints(model, group, effector.parent_link, torso)
        return (group, joints) if joints else None
    own = set(srdf.groups[effector.group].joints)
    found = []
    for group in srdf.groups.values():
        joints = _arm_joints(model, group, effector.parent_link, torso)
        if not joints or own & set(group.joints):
            continue
        if model.joints[joints[-1]].child == effector.parent_link:
            found.append(((torso in group.joints, len(group.joints), group.name), group, joints))
    if not found:
        return None
    _, group, joints = min(found, key=lambda entry: entry[0])
    return group, joints


def _parking(srdf: Srdf, joints: list[str]) -> tuple[str, dict[str, float]] | None:
    """The preferred named state that sets every one of ``joints``, and its values."""
    states = [s for s in srdf.states if set(joints) <= set(s.values)]
    for word in PARKING_WORDS:
        for state in states:
            if word in state.name.lower():
                return state.name, {j: round(state.values[j], 6) for j in joints}
    return None


def srdf_arms(
    model: RobotModel,
    desc: RobotDescription,
    srdf: Srdf,
    why: dict[str, str],
    doubts: dict[str, str],
) -> RobotDescription:
    """``desc`` with arms, parking and allowed contacts from ``srdf``; notes in why/doubts."""
    arms = dict(desc.arms)
    by_link = {arm.end_effector_link: key for key, arm in arms.items()}
    name = srdf.source.name
    for effector in srdf.end_effectors:
        key = by_link.get(effector.parent_link)
        found = _arm_group(model, srdf, effector, desc.torso_joint)
        if key is None or found is None:
            what = "drafted arm" if key is None else "group of arm joints"
            doubts[f"srdf.{effector.name}"] = (
                f"{name}'s end effector {effector.name!r} on {effector.parent_link!r} matches no "
                f"{what}: add or edit the arm by hand"
            )
            continue
        group, joints = found
        arms[key] = _srdf_arm(arms[key], model, srdf, group, joints, why, doubts)
        why[f"arms.{key}.end_effector_link"] = (
            f"{name}: end effector {effector.name!r} (group {effector.group!r}) hangs on it"
        )
    pairs = tuple(p for p in srdf.disabled_pairs if p not in desc.allowed_contacts)
    if pairs:
        why["allowed_contacts"] = (
            f"{name}'s {len(pairs)} disable_collisions pairs: links MoveIt found adjacent "
            "or never touching"
        )
    return replace(desc, arms=arms, allowed_contacts=(*desc.allowed_contacts, *pairs))


def _srdf_arm(
    arm: ArmDescription,
    model: RobotModel,
    srdf: Srdf,
    group: SrdfGroup,
    joints: list[str],
    why: dict[str, str],
    doubts: dict[str, str],
) -> ArmDescription:
    """``arm`` with the joints of ``group`` and, if the SRDF names one, its parking state."""
    path, name = f"arms.{arm.name}", srdf.source.name
    why[f"{path}.base_link"] = f"{name}: parent of the first joint of group {group.name!r}"
    parking = dict(arm.parking)
    state = _parking(srdf, joints)
    if state is not None:
        parking = state[1]
        why[f"{path}.parking"] = (
            f"{name}: named state {state[0]!r} (the first of {', '.join(PARKING_WORDS)} "
            "found in a state's name)"
        )
        doubts.pop(f"{path}.parking", None)
    else:
        if set(joints) != set(parking):
            drafted = drafted_parking(model, joints, arm.end_effector_link)
            parking = drafted.values
            why[f"{path}.parking"] = drafted.why
        doubts[f"{path}.parking"] = (
            f"{name} has no state named {' or '.join(PARKING_WORDS)} for group "
            f"{group.name!r}: the draft's own pose; `robocram robot check` drives it"
        )
    return replace(
        arm,
        base_link=model.joints[joints[0]].parent,
        joints=tuple(joints),
        parking=parking,
    )

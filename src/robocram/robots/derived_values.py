"""Values a description may leave out, derived from its URDF at load.

- a gripper's open and closed positions: its joints' upper and lower limits;
- its fingers (``gripper_links``): the links its joints (and their mimic followers) move;
- its widest opening [m]: the largest growth of a distance between two finger links from
  closed to open, plus the gap their shapes keep closed where that is a jaw's stop (3 cm
  or more: Kevin's 59 mm) rather than pads; for a single jaw moving against a fixed one
  (whose link frames sit on the pivot and do not part), how far the middle of the moving
  jaw leaves the tool frame's approach axis;
- the hand (``hand_links``): the wrist and every link below it; a suction hand's
  ``gripper_links`` are its hand links (what touches what it holds);
- a camera's minimal and maximal height: its frame's height with the torso at its lower
  and upper limit, the neck parked.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

import numpy as np

from robocram.robots.description import ArmDescription, CameraDescription, RobotDescription
from robocram.robots.description_check import check_values
from robocram.robots.errors import GripperDescriptionError
from robocram.robots.gripper import GripperDescription, GripperJoint
from robocram.robots.link_centre import link_centre, link_points
from robocram.robots.model_pose import finite_limits, link_pose, link_poses, subtree_links
from robocram.robots.robot_model import RobotModel
from robocram.tf import Pose

ARM_CAMERA_JOINTS = 3  # a camera this many joints move (no head) rides on an arm
ARM_CAMERA_SAMPLES = 128  # arm configurations sampled for a wrist camera's heights
ARM_CAMERA_SHARE = 0.9  # the quantile of those heights taken as its maximal height
ARM_CAMERA_SEED = 0  # the configurations are the same at every load
MIN_OPENING = 1e-4  # [m] a smaller growth of the finger gap means no opening was found
MIN_CLOSED_GAP = 0.03  # [m] closed fingers this far apart are stopped by their joints' limits


def derive_arm(robot_name: str, arm: ArmDescription, model: RobotModel) -> ArmDescription:
    """``arm`` with its gripper, fingers and hand filled in from the model where empty."""
    gripper = _gripper(robot_name, arm, model)
    hand = arm.hand_links or subtree_links(model, arm.end_effector_link)
    if gripper is None:
        return replace(arm, hand_links=hand)
    if gripper.is_suction:
        touching = arm.gripper_links or hand
        return replace(
            arm, gripper=gripper, gripper_joints=(), gripper_links=touching, hand_links=hand
        )
    fingers = arm.gripper_links or moved_links(model, gripper.names)
    if gripper.max_opening is None:
        opening = widest_opening(model, gripper, fingers)
        if opening is None:
            opening = single_jaw_opening(model, gripper, fingers, arm.tool_frame)
        gripper = replace(gripper, max_opening=opening)
    return replace(
        arm,
        gripper=gripper,
        gripper_joints=gripper.names,
        gripper_links=fingers,
        hand_links=hand,
    )


def _gripper(robot_name: str, arm: ArmDescription, model: RobotModel) -> GripperDescription | None:
    """The arm's gripper as given, or the parallel default from its gripper joints' limits."""
    gripper = arm.gripper
    if gripper is not None and gripper.curled_hand and not gripper.joints:
        gripper = replace(gripper, joints=curling_joints(model, arm.end_effector_link))
    if gripper is None:
        if not arm.gripper_joints:
            return None
        gripper = GripperDescription(
            tuple(_from_limits(robot_name, arm.name, model, j) for j in arm.gripper_joints)
        )
    elif arm.gripper_joints and tuple(arm.gripper_joints) != gripper.names:
        raise GripperDescriptionError(
            robot_name,
            arm.name,
            f"gripper_joints {arm.gripper_joints} differ from the gripper's {gripper.names}",
            "give only ArmDescription.gripper (gripper_joints follow from it)",
        )
    _check_gripper(robot_name, arm.name, model, gripper)
    return gripper


def curling_joints(model: RobotModel, wrist: str) -> tuple[GripperJoint, ...]:
    """Joints below ``wrist`` straight at 0 that curl to their upper limit, in file order.

    Open at 0, closed at the upper limit: a hand whose URDF does not couple its fingers.
    """
    found: list[GripperJoint] = []

    def below(link: str) -> None:
        for joint in model.joints.values():
            if joint.parent != link:
                continue
            curls = joint.type == "revolute" and joint.mimic is None and joint.lower == 0.0
            if curls and joint.upper is not None and joint.upper > 0.0:
                found.append(GripperJoint(joint.name, open=0.0, closed=joint.upper))
            below(joint.child)

    below(wrist)
    return tuple(found)


def _from_limits(robot_name: str, arm: str, model: RobotModel, name: str) -> GripperJoint:
    limits = finite_limits(model.joints[name])
    if limits is None:
        raise GripperDescriptionError(
            robot_name,
            arm,
            f"joint {name!r} has no finite limits to open and close between",
            f"give ArmDescription.gripper=GripperDescription((GripperJoint({name!r}, "
            "open=..., closed=...),))",
        )
    return GripperJoint(name, open=limits[1], closed=limits[0])


def _check_gripper(
    robot_name: str, arm: str, model: RobotModel, gripper: GripperDescription
) -> None:
    if gripper.is_suction:
        if gripper.joints or gripper.max_opening is not None:
            raise GripperDescriptionError(
                robot_name,
                arm,
                "a suction gripper has no joints and no opening",
                "give GripperDescription.suction() alone, or a gripper of fingers",
            )
        return
    if not gripper.joints and gripper.curled_hand:
        raise GripperDescriptionError(
            robot_name,
            arm,
            "GripperDescription.curling() found no joint below the wrist that is straight "
            "at 0 and curls to a positive upper limit",
            "list the hand's joints as GripperJoint(name, open=..., closed=...)",
        )
    if not gripper.joints:
        raise GripperDescriptionError(
            robot_name, arm, "the gripper has no joints", "list at least one GripperJoint"
        )
    for joint in gripper.joints:
        if joint.open == joint.closed:
            raise GripperDescriptionError(
                robot_name,
                arm,
                f"joint {joint.name!r} is open and closed at the same value {joint.open}",
                "give different open and closed values (within the joint's limits)",
            )
        check_values(robot_name, model, {joint.name: joint.open})
        check_values(robot_name, model, {joint.name: joint.closed})
    opening = gripper.max_opening
    if opening is not None and not (math.isfinite(opening) and opening > 0):
        raise GripperDescriptionError(
            robot_name,
            arm,
            f"max_opening {opening} is no positive distance",
            "give the widest gap between the fingers in metres, or None to derive it",
        )


def moved_links(model: RobotModel, joints: tuple[str, ...]) -> tuple[str, ...]:
    """Links below ``joints`` and below the mimic joints that follow them."""
    movers = set(joints)
    for joint in model.joints.values():
        if joint.mimic is not None and joint.mimic.joint in movers:
            movers.add(joint.name)
    links = (subtree_links(model, model.joints[j].child) for j in sorted(movers))
    return tuple(dict.fromkeys(itertools.chain.from_iterable(links)))


def widest_opening(
    model: RobotModel, gripper: GripperDescription, fingers: tuple[str, ...]
) -> float | None:
    """Largest growth [m] of the distance between two finger links from closed to open,
    plus the gap their shapes keep when closed if that is :data:`MIN_CLOSED_GAP` or more.

    With fingers that touch when closed the growth is the widest gap between them; ``None``
    when no two fingers move apart (a single finger, or links the joints do not move).
    Fingers whose joints' limits stop them apart (Kevin's stay 59 mm apart) open by the
    growth beyond that gap; a smaller closed gap is finger pads or the bounds of meshes
    (Boxy 6.5 mm, Baxter 16 mm) and is not added.
    """
    at_closed = link_poses(model, fingers, gripper.at(0.0))
    at_open = link_poses(model, fingers, gripper.at(1.0))
    closed = [at_closed[f].position for f in fingers]
    opened = [at_open[f].position for f in fingers]
    pairs = itertools.combinations(range(len(fingers)), 2)
    growth, i, j = max(
        (
            (math.dist(opened[i], opened[j]) - math.dist(closed[i], closed[j]), i, j)
            for i, j in pairs
        ),
        default=(0.0, 0, 0),
    )
    if growth <= MIN_OPENING:
        return None
    if gripper.curled_hand:
        return growth
    apart = np.asarray(opened[i]) - np.asarray(opened[j])
    gap = closed_gap(model, gripper, (fingers[i], fingers[j]), apart / np.linalg.norm(apart))
    return growth + gap if gap >= MIN_CLOSED_GAP else growth


def closed_gap(
    model: RobotModel, gripper: GripperDescription, pair: tuple[str, str], apart: np.ndarray
) -> float:
    """Gap [m] between two closed fingers' collision shapes along ``apart`` (the way the
    first moves from the second when opening); 0 when either has no readable shape."""
    faces = []
    for finger in pair:
        points = link_points(model.link(finger))
        if points is None:
            return 0.0
        pose = link_pose(model, finger, gripper.at(0.0)).matrix()
        faces.append((points @ pose[:3, :3].T + pose[:3, 3]) @ apart)
    return float(faces[0].min() - faces[1].max())


def single_jaw_opening(
    model: RobotModel, gripper: GripperDescription, fingers: tuple[str, ...], tool_frame: str
) -> float | None:
    """Largest travel [m] of a moving jaw along the tool frame's opening axis (its y).

    A jaw turning against a fixed one keeps its link frame on the pivot; the middle of its
    collision shapes moves across the way the hand approaches, along the opening. Measured
    along the axis, not as a distance from the tool frame's origin, so it holds wherever
    between the jaws the tool frame sits. ``None`` without a tool frame in the model or
    when no jaw moves along the opening.
    """
    if tool_frame not in model.links:
        return None
    tool = link_pose(model, tool_frame, gripper.at(0.0)).matrix()
    origin, opening = tool[:3, 3], tool[:3, 1]

    def across(finger: str, fraction: float) -> float:
        centre = link_pose(model, finger, gripper.at(fraction)) * Pose(
            link_centre(model.link(finger))
        )
        return float((np.asarray(centre.position) - origin) @ opening)

    growth = max((abs(across(f, 1.0) - across(f, 0.0)) for f in fingers), default=0.0)
    return growth if growth > MIN_OPENING else None


def derive_camera(
    desc: RobotDescription, model: RobotModel, cam: CameraDescription
) -> CameraDescription:
    """``cam`` with missing heights taken at the torso's limits, the neck parked."""
    if cam.minimal_height is not None and cam.maximal_height is not None:
        return cam
    base = dict(desc.neck_parking)
    torso = desc.torso_joint
    limits = finite_limits(model.joints[torso]) if torso is not None else None
    stops = [base] if limits is None else [{**base, torso: value} for value in limits]
    heights = [link_pose(model, cam.frame, joints).position[2] for joints in stops]
    heights.append(max(heights[-1], _arm_raised_height(desc, model, cam.frame, stops[-1])))
    return replace(
        cam,
        minimal_height=min(heights) if cam.minimal_height is None else cam.minimal_height,
        maximal_height=max(heights) if cam.maximal_height is None else cam.maximal_height,
    )


def _arm_raised_height(
    desc: RobotDescription, model: RobotModel, frame: str, joints: dict[str, float]
) -> float:
    """How high an arm carrying the camera (no head, no neck: a wrist camera) commonly
    holds it: the :data:`ARM_CAMERA_SHARE` quantile of its height over seeded arm
    configurations within the limits (``joints`` held). A camera no arm carries: -inf.

    Plans choose where to look from by the camera's heights; a wrist camera's parked
    height (a mobile arm's, under a counter's top) would rule out every counter.
    """
    if desc.pan_tilt is not None or desc.neck_arm is not None:
        return -math.inf
    chain = model.chain(model.root_link, frame)
    moving = [j for j in chain if j.movable and j.mimic is None and j.name != desc.torso_joint]
    if len(moving) < ARM_CAMERA_JOINTS:
        return -math.inf
    low, high = zip(*(finite_limits(j) or (-math.pi, math.pi) for j in moving), strict=True)
    rng = np.random.default_rng(ARM_CAMERA_SEED)
    samples = rng.uniform(low, high, (ARM_CAMERA_SAMPLES, len(moving)))
    names = [j.name for j in moving]
    heights = [
        link_pose(model, frame, {**joints, **dict(zip(names, row, strict=True))}).position[2]
        for row in samples.tolist()
    ]
    return float(np.quantile(heights, ARM_CAMERA_SHARE))


def derive_links(desc: RobotDescription, model: RobotModel) -> dict[str, object]:
    """The torso link and the pan-tilt links, where left out: the joints' child links.

    Returns the changed fields only (for ``LoadedDescription.checked``). Without this a
    torso given by its joint alone would yield no ``robot_torso_link_joint/3`` fact, and
    plans would think the robot has no torso.
    """
    changes: dict[str, object] = {}
    if desc.torso_link is None and desc.torso_joint is not None:
        changes["torso_link"] = model.joints[desc.torso_joint].child
    pt = desc.pan_tilt
    if pt is not None and (pt.pan_link is None or pt.tilt_link is None):
        changes["pan_tilt"] = replace(
            pt,
            pan_link=pt.pan_link or model.joints[pt.pan_joint].child,
            tilt_link=pt.tilt_link or model.joints[pt.tilt_joint].child,
        )
    return changes

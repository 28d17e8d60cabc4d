"""Check a robot description against its model: names first, then what the values mean.

Every named joint, link and frame must exist; all such problems are reported together,
each with the closest existing names. The semantic checks then look at the loaded model:
where the tool frame points, where the camera looks, what the torso lifts, and what was
left empty that plans need.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace

from robocram.robots.description import (
    ArmDescription,
    CameraDescription,
    LoadedDescription,
    RobotDescription,
)
from robocram.robots.errors import (
    DescriptionCheckError,
    JointValueError,
    NameProblem,
    closest_names,
)
from robocram.robots.findings import Finding
from robocram.robots.model_pose import finite_limits, link_pose
from robocram.robots.robot_model import RobotModel
from robocram.tf.quaternion import rotate

_LIMIT_SLACK = 1e-6  # [rad | m] tolerance on description values at a limit


class _Checker:
    def __init__(self, model: RobotModel) -> None:
        self.model = model
        self.problems: list[NameProblem] = []

    def links(self, names: Iterable[str | None], where: str, kind: str = "link") -> None:
        for name in names:
            if name is not None and name not in self.model.links:
                close = closest_names(name, self.model.links)
                self.problems.append(NameProblem(kind, name, where, close))

    def joints(self, names: Iterable[str | None], where: str) -> None:
        for name in names:
            if name is None:
                continue
            joint = self.model.joints.get(name)
            if joint is None:
                close = closest_names(name, self.model.joints)
                self.problems.append(NameProblem("joint", name, where, close))
            elif not joint.movable:
                close = closest_names(name, (j.name for j in self.model.movable_joints()))
                self.problems.append(
                    NameProblem(f"movable joint ({joint.type})", name, where, close)
                )

    def arm(self, key: str, arm: ArmDescription) -> None:
        where = f"arms[{key!r}]"
        if arm.name != key:
            self.problems.append(NameProblem("arm name", arm.name, where, (key,)))
        self.links([arm.end_effector_link, arm.base_link], f"{where}.end_effector_link/base_link")
        self.links([arm.tool_frame], f"{where}.tool_frame", kind="frame")
        self.links(arm.links, f"{where}.links")
        self.links(arm.gripper_links, f"{where}.gripper_links")
        self.links(arm.hand_links, f"{where}.hand_links")
        self.joints(arm.joints, f"{where}.joints")
        self.joints(arm.gripper_joints, f"{where}.gripper_joints")
        self.joints(arm.gripper.names if arm.gripper else (), f"{where}.gripper.joints")
        self.joints(arm.parking, f"{where}.parking")
        self.joints(arm.carrying, f"{where}.carrying")


def check_names(desc: RobotDescription, model: RobotModel) -> None:
    """Raise :class:`DescriptionCheckError` listing every name ``model`` does not have."""
    check = _Checker(model)
    check.links([desc.base_frame, desc.torso_link], "base_frame/torso_link")
    check.joints([desc.torso_joint], "torso_joint")
    for key, arm in desc.arms.items():
        check.arm(key, arm)
    for i, camera in enumerate(desc.cameras):
        check.links([camera.frame], f"cameras[{i}].frame", kind="frame")
    if desc.pan_tilt is not None:
        pt = desc.pan_tilt
        check.links([pt.pan_link, pt.tilt_link], "pan_tilt links")
        check.joints([pt.pan_joint, pt.tilt_joint], "pan_tilt joints")
    check.joints(desc.neck_parking, "neck_parking")
    check.joints(desc.stance, "stance")
    check.joints(desc.acceleration_limits, "acceleration_limits")
    check.links(desc.decomposed_links, "decomposed_links")
    if desc.neck_arm is not None and desc.neck_arm not in desc.arms:
        close = closest_names(desc.neck_arm, desc.arms)
        check.problems.append(NameProblem("arm", desc.neck_arm, "neck_arm", close))
    if check.problems:
        raise DescriptionCheckError(desc.name, model.source, check.problems)


def infer_arm(arm: ArmDescription, model: RobotModel) -> ArmDescription:
    """Fill an arm's empty joints and links from the chain ``base_link..end_effector_link``."""
    if arm.base_link is None:
        if not arm.joints:
            raise DescriptionCheckError(
                arm.name,
                model.source,
                [
                    NameProblem(
                        "base_link", "None", f"arms[{arm.name!r}]; give joints or a base_link", ()
                    )
                ],
            )
        links = arm.links or tuple(model.joints[j].child for j in arm.joints)
        return _replace_arm(arm, arm.joints, links)
    chain = model.chain(arm.base_link, arm.end_effector_link)
    movable = tuple(j.name for j in chain if j.movable)
    stray = [j for j in arm.joints if j not in movable]
    if stray:
        problems = [
            NameProblem("chain joint", j, f"arms[{arm.name!r}].joints", movable[:3]) for j in stray
        ]
        raise DescriptionCheckError(arm.name, model.source, problems)
    links = arm.links or tuple(j.child for j in chain)
    return _replace_arm(arm, arm.joints or movable, links)


def _replace_arm(
    arm: ArmDescription, joints: tuple[str, ...], links: tuple[str, ...]
) -> ArmDescription:
    return replace(arm, joints=joints, links=links)


def check_values(robot_name: str, model: RobotModel, states: Mapping[str, float]) -> None:
    """Raise :class:`JointValueError` for a joint value that is not finite or lies outside
    the joint's limits (a continuous joint's included: inf is no angle)."""
    for name, value in states.items():
        joint = model.joints[name]
        lower = -math.inf if joint.lower is None else joint.lower
        upper = math.inf if joint.upper is None else joint.upper
        if not (math.isfinite(value) and lower - _LIMIT_SLACK <= value <= upper + _LIMIT_SLACK):
            raise JointValueError(robot_name, name, value, lower, upper)


def semantic_findings(desc: LoadedDescription) -> tuple[Finding, ...]:
    """What a loaded description gets wrong or leaves doubtful beyond its names.

    Faults: a tool frame whose x (approach) points back at the wrist, a camera looking
    backwards, minimal above maximal camera height, a torso joint that does not lift the
    arms' bases. Warnings: a camera frame that is not optical (z forward), and anything
    left empty that plans need (a gripper, a parking pose, a camera, its widest opening).
    """
    found: list[Finding] = []
    for key, arm in desc.arms.items():
        if key != desc.neck_arm:
            found += _tool_frame_findings(desc.model, key, arm)
    for i, camera in enumerate(desc.cameras):
        found += _camera_findings(desc, i, camera)
    found += _torso_findings(desc)
    found += _gap_findings(desc)
    return tuple(found)


_AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1)}
_AXES["-z"] = (0, 0, -1)
_CAN_JUDGE = 1e-3  # [m] closer frames have no direction between them
_AWAY = 0.5  # cos of the largest angle [rad] between tool x and wrist-to-tool (60 degrees)


def _direction(a: Sequence[float], b: Sequence[float]) -> tuple[float, float, float] | None:
    """Unit vector from ``a`` to ``b``, None when they (nearly) coincide."""
    d = [q - p for p, q in zip(a, b, strict=True)]
    norm = math.sqrt(sum(c * c for c in d))
    return None if norm < _CAN_JUDGE else (d[0] / norm, d[1] / norm, d[2] / norm)


def _nearest_axis(direction: Sequence[float]) -> str:
    return max(_AXES, key=lambda k: sum(a * b for a, b in zip(_AXES[k], direction, strict=True)))


def _tool_frame_findings(model: RobotModel, key: str, arm: ArmDescription) -> list[Finding]:
    """The tool frame's x must point away from the wrist (the approach direction)."""
    wrist_in_tool = link_pose(model, arm.tool_frame).inverse() * link_pose(
        model, arm.end_effector_link
    )
    away = _direction(wrist_in_tool.position, (0.0, 0.0, 0.0))
    if away is None or away[0] >= _AWAY:
        return []
    axis = _nearest_axis(away)
    return [
        Finding(
            "fault",
            f"arms[{key!r}].tool_frame",
            f"{arm.tool_frame!r} has x pointing {_degrees(away[0])} deg off the direction "
            f"away from the wrist {arm.end_effector_link!r}, which is its {axis} axis",
            f"turn the tool frame so that its x is that {axis} axis (x = approach, "
            "y = opening; add a FrameSpec on top of it)",
        )
    ]


def _degrees(cosine: float) -> int:
    return round(math.degrees(math.acos(max(-1.0, min(1.0, cosine)))))


def _camera_findings(desc: LoadedDescription, i: int, camera: CameraDescription) -> list[Finding]:
    """Heights in order; the optical z looking forward (x forward: a body frame, warned)."""
    where = f"cameras[{i}]"
    found = []
    low, high = camera.height_range()
    if low > high:
        found.append(
            Finding(
                "fault",
                where,
                f"minimal_height {low} m is above maximal_height {high} m",
                "swap them, or leave both None to derive them from the torso's limits",
            )
        )
    # as the robot looks: an arm carrying the camera (a hand camera) parked, the neck too
    parked = {j: v for arm in desc.arms.values() for j, v in arm.parking.items()}
    rotation = link_pose(desc.model, camera.frame, {**parked, **desc.neck_parking}).orientation
    z_forward = rotate(rotation, (0.0, 0.0, 1.0))[0]
    x_forward = rotate(rotation, (1.0, 0.0, 0.0))[0]
    if z_forward > _CAMERA_FORWARD:
        return found
    if x_forward > _AWAY:
        found.append(
            Finding(
                "warning",
                f"{where}.frame",
                f"{camera.frame!r} looks along its x, not its z: not an optical frame",
                "name the camera's optical frame (z forward, x right, y down), often "
                "'<camera>_optical_frame', or add one with a FrameSpec",
            )
        )
        return found
    found.append(
        Finding(
            "fault",
            f"{where}.frame",
            f"{camera.frame!r} looks {_degrees(z_forward)} deg away from the robot's forward "
            f"x (its z in {desc.base_frame!r} with the neck and arms parked)",
            "name the camera's optical frame (z forward), or fix neck_parking to face ahead "
            "(for a hand camera: the parking of the arm carrying it)",
        )
    )
    return found


_CAMERA_FORWARD = 0.1  # cos: the optical z at most ~84 deg off the base's x (looking down)
_VERTICAL = 0.9  # cos of the largest angle between a torso's lift and the vertical
_LIFTS = 1e-3  # [m] an arm base moving less than this is not moved by the torso


def _torso_findings(desc: LoadedDescription) -> list[Finding]:
    """The torso joint must move every arm's base, and vertically."""
    torso = desc.torso_joint
    if torso is None:
        return []
    limits = finite_limits(desc.model.joints[torso])
    if limits is None:
        return []
    moves = []
    for key, arm in desc.arms.items():
        if key == desc.neck_arm or not arm.joints:
            continue
        base = desc.model.joints[arm.joints[0]].parent
        a, b = (link_pose(desc.model, base, {torso: v}).position for v in limits)
        moves.append((key, math.dist(a, b), abs(b[2] - a[2])))
    bad = [(k, d, dz) for k, d, dz in moves if d < _LIFTS or dz < _VERTICAL * d]
    if not bad:
        return []
    key, d, dz = bad[0]
    how = "does not move" if d < _LIFTS else f"moves it {d:.3f} m but only {dz:.3f} m up"
    return [
        Finding(
            "fault",
            "torso_joint",
            f"{torso!r} {how} the base of arm {key!r} over its limits",
            "name the prismatic joint that lifts the arms (not a head or finger joint), "
            "or None if the robot has no torso",
        )
    ]


def _gap_findings(desc: LoadedDescription) -> list[Finding]:
    """Warnings for what plans need that the description leaves empty."""
    if desc.flying:
        return []
    arms = {k: a for k, a in desc.arms.items() if k != desc.neck_arm}
    found = [gap for key, arm in arms.items() for gap in _arm_gaps(f"arms[{key!r}]", arm)]
    if arms and not desc.cameras:
        found.append(_gap("cameras", "none: looking and detecting fail", _CAMERA_FIX))
    return found


_CAMERA_FIX = "give a CameraDescription for the camera's optical frame"


def _gap(subject: str, problem: str, fix: str) -> Finding:
    return Finding("warning", subject, problem, fix)


def _arm_gaps(where: str, arm: ArmDescription) -> list[Finding]:
    found = []
    if arm.gripper is None:
        found.append(
            _gap(
                where,
                "no gripper: picking up with it fails",
                "give gripper_joints (or gripper=GripperDescription(...))",
            )
        )
    elif arm.gripper.max_opening is None and not arm.gripper.is_suction:
        found.append(
            _gap(
                f"{where}.gripper",
                "its widest opening cannot be derived (no two finger links move apart, and no "
                "jaw leaves the tool frame's approach axis)",
                "give GripperDescription(max_opening=<metres>)",
            )
        )
    if not arm.parking:
        found.append(
            _gap(
                f"{where}.parking",
                "empty: parking the arms leaves this arm where it is",
                "give joint values to park it",
            )
        )
    return found

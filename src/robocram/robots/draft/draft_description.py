"""Draft a robot description from a URDF: every guess with its reason, doubts marked.

``draft_description(urdf)`` reads the URDF's structure only (no physics, no IK) and
returns a :class:`DraftDescription`: the ``RobotDescription`` it guessed, why it guessed
each part, and where the URDF left doubt. ``source()`` prints it as ready-to-edit Python.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path

from robocram.robots.arm_envelope import lift_joints
from robocram.robots.description import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    RobotDescription,
)
from robocram.robots.description_check import infer_arm
from robocram.robots.draft.arms import arm_names, draft_arm
from robocram.robots.draft.base_drive import find_base_drive
from robocram.robots.draft.camera_reach import arm_camera_instead
from robocram.robots.draft.camera_sensors import camera_sensors
from robocram.robots.draft.cameras import (
    DEFAULT_HFOV,
    DEFAULT_VFOV,
    Neck,
    camera_frames,
    carrying_arm,
    find_camera,
    find_neck,
    likely_camera_link,
)
from robocram.robots.draft.draft_source import draft_source
from robocram.robots.draft.hands import find_fixed_hands, find_hands
from robocram.robots.draft.hull_overreach import overreaching_links
from robocram.robots.draft.link_poses import link_poses, within_limits
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.draft.parking import neck_pose
from robocram.robots.draft.srdf_arms import srdf_arms
from robocram.robots.draft.stance import drafted_stance
from robocram.robots.draft.stowing import (
    ABOVE,
    AHEAD,
    CameraView,
    looking_pose,
    parked_unclear,
    stowed_pose,
)
from robocram.robots.draft.telescope import Telescope, find_telescopes
from robocram.robots.draft.torso import find_torso
from robocram.robots.draft.trunk import find_trunk
from robocram.robots.draft.trunk_stance import upright_trunk
from robocram.robots.hand_shapes import with_hand_shapes
from robocram.robots.robot_model import RobotModel
from robocram.robots.self_contacts import SelfContacts
from robocram.robots.srdf import read_srdf
from robocram.tf import Pose

PAN_SWEEP = math.radians(60.0)  # [rad] a head's pan a parked arm it turns stays clear in
PAN_STEPS = 4  # turns checked each way within the sweep (every 15 degrees)


@dataclass(frozen=True)
class DraftDescription:
    """A drafted description with a reason per guessed field and the doubts left.

    ``why`` and ``doubts`` are keyed by the field's path (``"torso_joint"``,
    ``"arms.left.tool_frame"``, ``"cameras.0"``).
    """

    description: RobotDescription
    urdf: Path
    why: Mapping[str, str] = field(default_factory=dict)
    doubts: Mapping[str, str] = field(default_factory=dict)
    inferred_joints: frozenset[str] = frozenset()  # arms whose joints loading infers alike

    def source(self, module_file: Path | None = None) -> str:
        """The description as a Python module defining ``description()``.

        With ``module_file`` (where the text will be saved) the URDF path is written
        relative to it, so the folder can move; else absolute.
        """
        return draft_source(
            self.description, self.why, self.doubts, module_file, self.inferred_joints
        )


def draft_description(
    urdf: str | Path,
    name: str | None = None,
    srdf: str | Path | None = None,
    package_paths: Iterable[str | Path] = (),
    camera: str | None = None,
) -> DraftDescription:
    """Guess a description of the robot in ``urdf`` (its name from the URDF unless given).

    An ``srdf`` (its MoveIt configuration) gives the arms' joints, parking states and
    self-contacts instead of guesses. ``package_paths`` are searched for ``package://``
    URIs; a package found nowhere gets boxes and a :class:`MissingMeshWarning`, so a
    draft can start before every mesh package is at hand. ``camera``: the camera's link
    where none is named like one (``robocram robot draft --camera LINK``).

    Raises:
        UrdfError: the URDF cannot be read or is not a tree.
        SrdfError: the SRDF cannot be read or names what the URDF does not have.
    """
    path = Path(urdf).expanduser().resolve()
    model = RobotModel.from_file(path, package_paths, missing_packages_as_boxes=True)
    why: dict[str, str] = {"base_frame": "the URDF's root link: the robot's base"}
    doubts: dict[str, str] = {}
    telescopes = find_telescopes(ModelTree(model))
    for telescope in telescopes:
        model = model.with_coupling(telescope.coupling)
    if telescopes:
        why["coupled_joints"] = "; ".join(t.why for t in telescopes)
    semantics = None if srdf is None else read_srdf(srdf, model)
    tree = ModelTree(model)
    drive = find_base_drive(tree)
    _note(why, doubts, "base_type", drive.why, drive.doubt)
    hands = find_hands(tree) or find_fixed_hands(tree)
    shaped = with_hand_shapes(model, [h.end_effector_link for h in hands])
    if shaped is not model:  # as loading shapes them: the jaws' opening is measured on them
        model, tree = shaped, ModelTree(shaped)
    guessed = camera is None and not camera_frames(tree, [h.end_effector_link for h in hands])
    if guessed:  # as `--camera LINK` with the link the check would name
        camera = likely_camera_link(tree, [h.end_effector_link for h in hands])
    cameras = [c for c in _camera_guess(tree, [h.end_effector_link for h in hands], camera)]
    torso = find_torso(tree, [h.end_effector_link for h in hands], cameras)
    _note(why, doubts, "torso_joint", torso.why, torso.doubt)
    names, names_why, names_doubt = arm_names(tree, hands) if hands else ([], "", None)
    arms: dict[str, ArmDescription] = {}
    frames: list[FrameSpec] = []
    trunk = find_trunk(tree, [h.end_effector_link for h in hands] + cameras)
    cut, trunk_why = torso.joint, ""
    if trunk.joint is not None and trunk.joint != torso.joint:
        cut = trunk.joint
        trunk_why = f"; below the trunk that turns them all ({', '.join(trunk.joints)})"
    arms_cut = cut
    waist = find_trunk(tree, [h.end_effector_link for h in hands])
    if trunk.joint is None and waist.joint is not None and waist.joint != torso.joint:
        arms_cut = waist.joint  # a waist turning the arms and the head (Centauro's): the
        # arms share it, so each arm's parking would set it otherwise; the head pans with it
        trunk_why = f"; below the waist that turns both ({', '.join(waist.joints)})"
    for hand, arm_name in zip(hands, names, strict=True):
        drafted = draft_arm(tree, hand, arm_name, arms_cut)
        arms[arm_name] = drafted.arm
        roles = _roles(model, drafted.arm, telescopes)
        if roles:
            why[f"arms.{arm_name}.joints"] = roles
        frames += [drafted.added] if drafted.added is not None else []
        for key, text in drafted.why.items():
            why[f"arms.{arm_name}.{key}"] = text
        for key, text in drafted.doubts.items():
            doubts[f"arms.{arm_name}.{key}"] = text
    _note(why, doubts, "arms", (names_why or "no gripper-like end found") + trunk_why, names_doubt)
    if not hands:
        doubts["arms"] = "no chain ends in fingers (prismatic, mimic or leaf joints): add arms"
    desc = RobotDescription(
        name=name or model.name,
        urdf=path,
        base_frame=model.root_link,
        base_type=drive.base_type,
        torso_link=torso.link,
        torso_joint=torso.joint,
        arms=arms,
        extra_frames=tuple(frames),
        coupled_joints=tuple(t.coupling for t in telescopes),
    )
    stance = drafted_stance(model, [h.end_effector_link for h in hands])
    upright = upright_trunk(model, (trunk if trunk.joint is not None else waist).joints)
    if stance is not None or upright is not None:
        parts = [s for s in (stance, upright) if s is not None]
        values = {k: v for s in parts for k, v in s.values.items()}
        desc = replace(desc, stance=values)
        doubt = "; ".join(s.doubt for s in parts if s.doubt) or None
        _note(why, doubts, "stance", "; ".join(s.why for s in parts), doubt)
    overreach = overreaching_links(tree, drive.base_type == "fixed")
    if overreach.links:  # a hull filling a hollow its arms reach into: collided as parts
        desc = replace(desc, decomposed_links=overreach.links)
        why["decomposed_links"] = overreach.why
    chosen = None
    if camera is None and drive.base_type == "fixed":  # one that cannot see the arms'
        # reach (a fixed robot cannot step back to see its table): the picking arm's
        instead = arm_camera_instead(tree, desc.arms, camera_sensors(path))
        camera, chosen = instead if instead is not None else (None, None)
    desc = _with_camera(tree, desc, why, doubts, cut, camera, guessed, chosen)
    desc = _parked_clear(tree, desc, why, doubts)
    if semantics is not None:
        desc = srdf_arms(model, desc, semantics, why, doubts)
    inferred = frozenset(
        key
        for key, arm in desc.arms.items()
        if infer_arm(replace(arm, joints=(), links=()), model).joints == arm.joints
    )
    return DraftDescription(desc, path, why, doubts, inferred)


def _roles(model: RobotModel, arm: ArmDescription, telescopes: list[Telescope]) -> str:
    """Why an arm holds a lift or a telescope (empty for an arm of turning joints)."""
    parts = []
    lift = lift_joints(model, arm)
    if lift:
        parts.append(f"{', '.join(lift)} lifts this arm only, not the camera: its first joint")
    for telescope in telescopes:
        if telescope.coupling.actuator in arm.joints:
            parts.append(f"{telescope.coupling.actuator} drives the telescope (coupled_joints)")
    return "; ".join(parts)


def _camera_guess(tree: ModelTree, hands: list[str], given: str | None) -> list[str]:
    camera = find_camera(tree, hands, None, given=given)
    return [] if camera is None else [camera.added.parent if camera.added else camera.frame]


def _note(
    why: dict[str, str], doubts: dict[str, str], key: str, text: str, doubt: str | None
) -> None:
    why[key] = text
    if doubt:
        doubts[key] = doubt


def _with_camera(
    tree: ModelTree,
    desc: RobotDescription,
    why: dict[str, str],
    doubts: dict[str, str],
    cut: str | None,
    given: str | None = None,
    inferred: bool = False,
    chosen: str | None = None,
) -> RobotDescription:
    """``desc`` with its camera, heights at the torso limits, and pan-tilt or neck arm;
    ``given`` (or ``inferred``, or ``chosen``: why the draft took it) is judged with the
    arms parked, as the check does."""
    hands = [arm.end_effector_link for arm in desc.arms.values()]
    sensors = camera_sensors(Path(desc.urdf))
    carrier = None if given is None else _park_carrier(tree, desc, given, why, doubts)
    if carrier is not None:
        desc = replace(desc, arms={**desc.arms, carrier.name: carrier})
    parked = {j: v for arm in desc.arms.values() for j, v in arm.parking.items()}
    camera = find_camera(tree, hands, desc.torso_joint, sensors, given, parked, inferred, chosen)
    if camera is None:
        likely = likely_camera_link(tree, hands)
        doubts["cameras"] = (
            f"no camera link found by name: draft again with `--camera LINK` (likely "
            f"{likely!r}) to look and detect objects"
        )
        return desc
    others = f"; others: {', '.join(camera.others)}" if camera.others else ""
    _note(why, doubts, "cameras.0", camera.why + others, camera.doubt)
    sensor = camera.sensor
    if sensor is None:
        doubts["cameras.0.horizontal_fov"] = "the URDF gives no field of view: take the sensor's"
    else:
        pixels = f" at {sensor.size[0]} x {sensor.size[1]} pixels" if sensor.size else ""
        why["cameras.0.horizontal_fov"] = (
            f"the URDF's Gazebo sensor {sensor.name!r} on {sensor.reference}{pixels}"
        )
    frames = desc.extra_frames + ((camera.added,) if camera.added else ())
    spec = CameraDescription(
        frame=camera.frame,
        minimal_height=camera.minimal_height,
        maximal_height=camera.maximal_height,
        horizontal_fov=DEFAULT_HFOV if sensor is None else round(sensor.horizontal_fov, 4),
        vertical_fov=DEFAULT_VFOV if sensor is None else round(sensor.vertical_fov, 4),
    )
    looked_from = camera.added.parent if camera.added else camera.frame
    neck = find_neck(tree, looked_from, cut)
    if carrier is None:  # a camera found on an arm's wrist (the Donbot's) rides on it too
        carrier = _park_carrier(tree, desc, looked_from, why, doubts)
        if carrier is not None:
            desc = replace(desc, arms={**desc.arms, carrier.name: carrier})
    if carrier is not None:  # the arm's joints are not a neck too
        neck = Neck(None, (), f"the camera rides on arm {carrier.name!r}: its parking aims it")
    _note(why, doubts, "pan_tilt", neck.why, neck.doubt)
    offset = camera.added.pose if camera.added else Pose()
    parking = neck_pose(tree.model, neck.arm_joints, looked_from, offset) if neck.arm_joints else {}
    if neck.pan_tilt is not None:
        pt = neck.pan_tilt
        parking = {j: within_limits(tree.model, j, 0.0) for j in (pt.pan_joint, pt.tilt_joint)}
        why["neck_parking"] = "head at zero: straight ahead"
    arms = dict(desc.arms)
    if neck.arm_joints:
        arms["neck"] = ArmDescription(
            name="neck",
            end_effector_link=tree.model.joints[neck.arm_joints[-1]].child,
            tool_frame=camera.frame,
            base_link=tree.model.joints[neck.arm_joints[0]].parent,
            joints=neck.arm_joints,
            parking=parking,
        )
        why["arms.neck"] = "the joints between torso and camera form an arm that aims it"
        why["neck_parking"] = "sampled in limits (seed 0): the camera looks ahead, 30 deg down"
    return replace(
        desc,
        arms=arms,
        cameras=(spec,),
        pan_tilt=neck.pan_tilt,
        neck_arm="neck" if neck.arm_joints else None,
        neck_parking=parking,
        extra_frames=frames,
    )


def _camera_view(tree: ModelTree, desc: RobotDescription) -> CameraView | None:
    """The first camera's view in the root link with the neck parked, or None (no camera,
    or one an arm carries: its parking aims it)."""
    if not desc.cameras:
        return None
    camera = desc.cameras[0]
    added = {f.name: f for f in desc.extra_frames}
    spec = added.get(camera.frame)
    link = spec.parent if spec is not None else camera.frame
    if link not in tree.model.links or any(
        link in tree.subtree_links(arm.end_effector_link) or link == arm.end_effector_link
        for key, arm in desc.arms.items()
        if key != desc.neck_arm
    ):
        return None
    pose = link_poses(tree.model, dict(desc.neck_parking))[link]
    pose = pose * spec.pose if spec is not None else pose
    return CameraView(pose, camera.horizontal_fov, camera.vertical_fov)


def _pan_sweep(tree: ModelTree, desc: RobotDescription, arm: str) -> list[dict[str, float]]:
    """States of the head's pan joint a parked ``arm`` must stay clear in: at zero and
    every 15 degrees to :data:`PAN_SWEEP` each way (within limits), where the pan turns
    the arm too (a waist that turns the head and both arms, Centauro's); else only the
    robot as it is."""
    pan = desc.pan_tilt.pan_joint if desc.pan_tilt is not None else None
    base = desc.arms[arm].base_link
    if pan is None or base is None:
        return [{}]
    turned = tree.model.joints[pan].child
    if base != turned and base not in tree.subtree_links(turned):
        return [{}]
    turns = [PAN_SWEEP * k / PAN_STEPS for k in range(-PAN_STEPS, PAN_STEPS + 1) if k != 0]
    return [{}] + [{pan: within_limits(tree.model, pan, turn)} for turn in turns]


def _parked_clear(
    tree: ModelTree, desc: RobotDescription, why: dict[str, str], doubts: dict[str, str]
) -> RobotDescription:
    """``desc`` with each arm parked in the body camera's view, or into the robot when the
    head pans with it, stowed again clear of both (Centauro's elbow hung before its head
    camera; its waist pans the head and swung the parked hand into the pelvis)."""
    view = _camera_view(tree, desc)
    arms = dict(desc.arms)
    for key, arm in desc.arms.items():
        if key == desc.neck_arm or not arm.parking:
            continue
        swept = _pan_sweep(tree, desc, key)
        wrist = arm.end_effector_link
        if not parked_unclear(tree.model, arm.parking, wrist, view, swept):
            continue
        stowed = stowed_pose(
            tree.model, tuple(arm.parking), wrist, tree.model.derived(SelfContacts),
            view=view, swept=swept,
        )  # fmt: skip
        if stowed is None:
            doubts[f"arms.{key}.parking"] = (
                "parked, the arm hangs in the camera's view (or meets the robot as the head "
                "pans) and no stowed pose clear of both was found: give one"
            )
            continue
        arms[key] = replace(arm, parking=stowed.values)
        turning = " and clear as the head pans" if len(swept) > 1 else ""
        why[f"arms.{key}.parking"] = (
            f"stowed out of the camera's view{turning}: within limits, the arm within "
            f"{stowed.extent:.2f} m of the base's middle, 1 cm clear of its other links (meshes)"
        )
        doubts.pop(f"arms.{key}.parking", None)
    return replace(desc, arms=arms)


def _park_carrier(
    tree: ModelTree,
    desc: RobotDescription,
    camera: str,
    why: dict[str, str],
    doubts: dict[str, str],
) -> ArmDescription | None:
    """The arm carrying the given ``camera`` re-parked to look ahead over the robot (a
    stowed hand camera sees the robot's own body), or None if no arm carries it."""
    joints = {key: arm.joints or tuple(arm.parking) for key, arm in desc.arms.items()}
    key = carrying_arm(tree, camera, joints)
    if key is None:
        return None
    arm = desc.arms[key]
    looking = looking_pose(tree.model, tuple(arm.parking), arm.end_effector_link)
    if looking is None:
        return arm
    why[f"arms.{key}.parking"] = (
        f"it carries the camera: the wrist {AHEAD} m ahead of and {ABOVE} m above the "
        "shoulder, the hand below it, 1 cm clear of its other links (meshes)"
    )
    doubts.pop(f"arms.{key}.parking", None)
    return replace(arm, parking=looking.values)

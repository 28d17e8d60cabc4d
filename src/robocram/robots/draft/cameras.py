"""The camera and neck of a drafted robot: a camera frame, its heights and how it turns.

Camera frames are found by name (optical, camera, rgb, kinect, xtion, ...), scored: an
optical frame (z forward) first, then one on the head, then colour over depth. A frame
with x forward (ROS body convention) gets an optical frame added in code. Where no link is
named like a camera, the draft uses the likely link (as ``--camera LINK`` would), judged
with the arms parked, and adds a frame aimed ahead and down if its axes do not look ahead.
Two joints between the torso and the camera are a pan-tilt unit; more are a neck arm.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from robocram.robots.description import PanTiltDescription
from robocram.robots.draft.camera_sensors import CameraSensor, sensor_for
from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.link_centre import link_points
from robocram.robots.model_additions import FrameSpec
from robocram.tf import Pose
from robocram.tf import quaternion as quat

CAMERA_WORDS = ("optical", "camera", "rgb", "kinect", "xtion", "realsense", "stereo")
NOT_CAMERAS = ("depth", "infra", "_ir", "projector", "laser", "imu", "gazebo", "info")
FORWARD = 0.7  # x share in the root link of an axis that looks squarely forward
LOOKS_AHEAD = 0.5  # x share of an optical axis that `robot check` counts as looking ahead
OPTICAL_FROM_BODY = Pose.from_xyz_rpy((0.0, 0.0, 0.0), (-math.pi / 2, 0.0, -math.pi / 2))
DEFAULT_HFOV = math.radians(60.0)  # [rad] a common RGB-D camera; URDF links carry no FOV
DEFAULT_VFOV = math.radians(45.0)  # [rad]
AIM_DOWN = math.radians(30.0)  # [rad] an added optical frame looks this far below ahead,
AIM_FLOOR = 1.2  # [m] or less, so that its axis meets the floor no nearer than this
CAMERA_SIZE = 0.3  # [m] a camera's body spans less (a Kinect 0.28 m): a larger link carries one


@dataclass(frozen=True)
class Camera:
    """The drafted camera: its frame (maybe added), heights over the root link, and notes."""

    frame: str
    added: FrameSpec | None
    minimal_height: float  # [m]
    maximal_height: float  # [m]
    why: str
    others: tuple[str, ...]
    doubt: str | None = None
    sensor: CameraSensor | None = None  # the Gazebo sensor giving its fields of view


def _score(tree: ModelTree, link: str, hands: list[str]) -> float:
    name = link.lower()
    score = 4.0 * ("optical" in name) + 1.0 * ("rgb" in name or "color" in name)
    score += 1.0 * ("wide" in name) + 1.0 * ("head" in name)
    score -= 5.0 * any(tree.below(hand, link) for hand in hands)
    return score - 0.01 * len(name)


def camera_frames(tree: ModelTree, hands: list[str]) -> list[str]:
    """Frames that look like cameras, best first; hand cameras last. Where the best is a
    body larger than any camera (:data:`CAMERA_SIZE`) carrying others rigidly below it, it
    is their mount (Tracy's ``camera_pole``, a metre tall, its frame at the pole's foot,
    holds ``camera_mount`` and ``camera_link``): the best of those it carries that carries
    none itself comes first."""
    found = [
        link
        for link in tree.model.links
        if any(w in link.lower() for w in CAMERA_WORDS)
        and not any(w in link.lower() for w in NOT_CAMERAS)
    ]
    ranked = sorted(found, key=lambda link: -_score(tree, link, hands))
    if not ranked or not _structure(tree, ranked[0]):
        return ranked
    carried = [link for link in ranked if link in tree.fixed_closure(ranked[0])[1:]]
    ends = [link for link in carried if not set(found) & set(tree.fixed_closure(link)[1:])]
    return [*ends[:1], *(link for link in ranked if link not in ends[:1])]


def _structure(tree: ModelTree, link: str) -> bool:
    """Whether ``link``'s collision shapes span more than a camera's body does."""
    points = link_points(tree.model.link(link))
    return points is not None and float(np.ptp(points, axis=0).max()) > CAMERA_SIZE


HEAD_HEIGHT = 0.5  # [m] over the root: a link off the arms this high may carry a camera
LIKELY_WORDS = ("head", "sensor", "eye", "vision", "cam", "kinect", "xtion", "mast")
LIKELY_RULE = "the link off the arms named like a head or sensor, else the highest, else a wrist"


def likely_camera_link(tree: ModelTree, hands: Sequence[str]) -> str:
    """The link a camera most likely sits on when none is named like one (for ``--camera
    LINK``): off the arms, named like a head or a sensor, else high up (of links alike, the
    deepest); an arm on its own (nothing off it is named so or stands 0.5 m up): its wrist,
    for a hand camera."""
    poses = link_poses(tree.model)
    off_arms = [
        link
        for link in tree.model.links
        if not any(tree.below(hand, link) or tree.below(link, hand) for hand in hands)
    ]

    def score(link: str) -> tuple[int, float, int]:
        words = sum(word in link.lower() for word in LIKELY_WORDS)
        # among links alike and level, the deepest: past the joints that turn a head
        return words, round(poses[link].position[2], 3), len(tree.ancestors(link))

    best = max(off_arms, key=score, default=None)
    if best is not None and (score(best)[0] > 0 or score(best)[1] >= HEAD_HEIGHT or not hands):
        return best
    return hands[0] if hands else tree.model.root_link


def find_camera(
    tree: ModelTree,
    hands: list[str],
    torso: str | None,
    sensors: Sequence[CameraSensor] = (),
    given: str | None = None,
    parked: Mapping[str, float] | None = None,
    inferred: bool = False,
    chosen: str | None = None,
) -> Camera | None:
    """The robot's main camera with heights at the torso's limits, or None.

    ``sensors`` (the URDF's Gazebo cameras) give its fields of view where one images it;
    ``given``: the link the user named (``--camera LINK``), first whatever its name, its
    axes judged with the arms at ``parked`` (as ``robot check`` judges them); ``inferred``:
    ``given`` is :func:`likely_camera_link`'s guess, not the user's, and says so in a doubt;
    ``chosen``: why the draft took ``given`` itself (``camera_reach.py``: an arm's camera).
    """
    frames = camera_frames(tree, hands)
    if given is not None:
        tree.model.link(given)  # a DescriptionError names close links
        frames = [given, *(f for f in frames if f != given)]
    if not frames:
        return None
    frame, others = frames[0], tuple(frames[1:4])
    if given is None:
        found = f"camera frame by name ({len(frames)} found, best first)"
        added, why, doubt = _named_optics(tree, frame, found)
    else:
        added, why, doubt = _given_optics(tree, frame, parked or {}, inferred, chosen)
    low, high = _heights(tree, frame, torso)
    camera_frame = added.name if added is not None else frame
    sensor = sensor_for(frame, tree.rigid_group(frame), sensors)
    return Camera(camera_frame, added, low, high, why, others, doubt, sensor)


def looking_axis(axes: np.ndarray, optical: bool = True) -> str | None:
    """Which axis of a frame (rotation ``axes`` in the root link) looks ahead: ``"z"`` (an
    optical frame), ``"x"`` (ROS body convention), or None. A camera frame (named like
    one) not named ``optical`` (``optical`` False) whose x looks ahead and down while its z
    looks up is read by the body convention: a camera tilted steeply down onto a workspace
    (Tracy's ``camera_link``, 72 degrees), not an optical frame looking over it."""
    z_ahead, x_ahead = float(axes[0, 2]), float(axes[0, 0])
    if not optical and x_ahead > 0.0 and float(axes[2, 0]) < 0.0 < float(axes[2, 2]):
        return "x"
    if z_ahead >= FORWARD or (z_ahead >= LOOKS_AHEAD and z_ahead >= x_ahead):
        return "z"
    return "x" if x_ahead >= LOOKS_AHEAD else None


def _named_optics(
    tree: ModelTree, frame: str, found: str
) -> tuple[FrameSpec | None, str, str | None]:
    """A named camera's optical frame (maybe added), why, and a doubt, at zero joints."""
    axes = link_poses(tree.model)[frame].matrix()[:3, :3]
    z_ahead, x_ahead = float(axes[0, 2]), float(axes[0, 0])
    looking = looking_axis(axes, "optical" in frame.lower())
    if looking == "z":
        return None, found + "; optical: z looks forward", None
    if looking == "x":
        added = FrameSpec(f"{frame}_optical", frame, OPTICAL_FROM_BODY)
        why = "; its x looks forward (body convention): optical frame added, z forward"
        if x_ahead < LOOKS_AHEAD:  # tilted steeply down, its z looking up
            down = math.degrees(math.asin(min(1.0, -float(axes[2, 0]))))
            why = (
                f"; not named optical, its x looks {down:.0f} deg down, its z up (body "
                "convention): optical frame added, z along its x"
            )
        return added, found + why, None
    doubt = (
        f"neither its z (x share {z_ahead:.2f}) nor its x ({x_ahead:.2f}) looks ahead "
        f"(at least {LOOKS_AHEAD}, as `robot check` asks) at zero joints; add an "
        "optical frame (z forward, x right, y down) with a FrameSpec"
    )
    return None, found, doubt


def _given_optics(
    tree: ModelTree,
    frame: str,
    parked: Mapping[str, float],
    inferred: bool,
    chosen: str | None = None,
) -> tuple[FrameSpec | None, str, str | None]:
    """A given or inferred camera link's optical frame: its own axes where they look ahead
    with the arms parked, or where it is named like a camera and an arm carries it (the
    arm aims it: its z is its optical axis, Baxter's ``right_hand_camera_link`` looking
    along its hand); else an added frame aimed ahead and down (:func:`aim_down`)."""
    found = chosen if chosen is not None else "camera frame as given (--camera)"
    doubt = None
    if inferred:
        found = "camera frame inferred: no link is named like a camera; " + LIKELY_RULE
        doubt = (
            f"inferred, not read from the URDF: the camera is put on {frame!r}; if the "
            "robot's camera sits elsewhere, draft again with `robocram robot draft URDF "
            "--camera LINK`, or edit this frame"
        )
    pose = link_poses(tree.model, parked)[frame]
    axes = pose.matrix()[:3, :3]
    z_ahead, x_ahead = float(axes[0, 2]), float(axes[0, 0])
    looking = looking_axis(axes)  # a link given or inferred keeps no camera convention
    if looking == "z":
        return None, found + "; optical: z looks forward, the arms parked", doubt
    if looking == "x":
        added = FrameSpec(f"{frame}_optical", frame, OPTICAL_FROM_BODY)
        why = "; its x looks forward (body convention), the arms parked: optical frame added"
        return added, found + why, doubt
    if _named_camera(frame) and _on_an_arm(tree, frame, parked):
        why = (
            f"; named like a camera on an arm, which aims it: its own z is its optical axis "
            f"(x share {z_ahead:.2f}, the arms parked)"
        )
        return None, found + why, doubt
    down = aim_down(pose.position[2])
    added = FrameSpec(f"{frame}_optical", frame, aimed_optics(axes, down))
    why = (
        f"; neither its z (x share {z_ahead:.2f}) nor its x ({x_ahead:.2f}) looks ahead, "
        f"the arms parked: optical frame added looking ahead (the base's x), "
        f"{math.degrees(down):.0f} deg down"
    )
    return added, found + why, doubt


def _named_camera(frame: str) -> bool:
    low = frame.lower()
    return any(w in low for w in CAMERA_WORDS) and not any(w in low for w in NOT_CAMERAS)


def _on_an_arm(tree: ModelTree, frame: str, parked: Mapping[str, float]) -> bool:
    """Whether a joint an arm's parking sets moves ``frame``: an arm carries it."""
    return any(j.name in parked for j in tree.movable_ancestors(frame))


def aim_down(height: float) -> float:
    """How far [rad] below ahead a camera ``height`` [m] over the root looks: :data:`AIM_DOWN`,
    less where a low camera would look into the floor nearer than :data:`AIM_FLOOR`."""
    return min(AIM_DOWN, math.asin(min(1.0, max(0.0, height) / AIM_FLOOR)))


def aimed_optics(link_axes: np.ndarray, angle_down: float = AIM_DOWN) -> Pose:
    """The pose in a link (its axes in the root: ``link_axes``) of an optical frame that
    looks along the root's x, ``angle_down`` [rad] down, its image's x to the robot's right."""
    down, ahead = math.sin(angle_down), math.cos(angle_down)
    optical = np.column_stack(((0.0, -1.0, 0.0), (-down, 0.0, -ahead), (ahead, 0.0, -down)))
    local = np.asarray(link_axes).T @ optical
    return Pose(orientation=quat.normalized([round(v, 6) for v in quat.from_matrix(local)]))


def _heights(tree: ModelTree, frame: str, torso: str | None) -> tuple[float, float]:
    if torso is None:
        height = link_poses(tree.model)[frame].position[2]
        return round(height, 3), round(height, 3)
    joint = tree.model.joints[torso]
    ends = [v if v is not None and math.isfinite(v) else 0.0 for v in (joint.lower, joint.upper)]
    heights = [link_poses(tree.model, {torso: v})[frame].position[2] for v in ends]
    return round(min(heights), 3), round(max(heights), 3)


@dataclass(frozen=True)
class Neck:
    """How the camera turns: a pan-tilt unit, a neck arm's joints, or neither."""

    pan_tilt: PanTiltDescription | None
    arm_joints: tuple[str, ...]
    why: str
    doubt: str | None = None


def carrying_arm(
    tree: ModelTree, camera: str, arm_joints: Mapping[str, Sequence[str]]
) -> str | None:
    """The arm (of ``arm_joints``, its joints by key) that carries ``camera``, or None: its
    parking aims the camera, and its joints must not be drafted again as a neck arm."""
    ancestors = {j.name for j in tree.movable_ancestors(camera)}
    return next((key for key, joints in arm_joints.items() if ancestors & set(joints)), None)


def find_neck(tree: ModelTree, camera: str, torso: str | None) -> Neck:
    """The joints between the torso (or root) and ``camera`` that turn it."""
    chain = tree.movable_ancestors(camera)
    names = [j.name for j in chain]
    if torso in names:
        chain = chain[names.index(torso) + 1 :]
    joints = [j for j in chain if j.mimic is None]
    if not joints:
        return Neck(None, (), "no joint turns the camera", "the robot cannot look around")
    if len(joints) >= 3:
        return Neck(None, tuple(j.name for j in joints), f"{len(joints)} joints turn the camera")
    poses = link_poses(tree.model)
    axes = [axis_in_root(tree.model, j.name, poses) for j in joints]
    if len(joints) == 1:
        only = f"only {joints[0].name} turns the camera: no pan-tilt, the camera looks ahead"
        return Neck(None, (), "one joint cannot aim a camera at a point", only)
    pan, tilt = joints
    why = "two joints turn the camera: the first pans, the second tilts"
    if abs(float(axes[1][2])) >= 0.9 and abs(float(axes[0][2])) <= 0.1:
        tilt, pan = joints  # TALOS's head tilts first, then pans
        why = "two joints turn the camera: the first tilts (horizontal axis), the second pans"
        axes = axes[::-1]
    doubt = None
    if abs(axes[0][2]) < 0.9 or abs(float(np.asarray(axes[1])[2])) > 0.1:
        doubt = "the first axis is not vertical or the second not horizontal"
    unit = PanTiltDescription(pan_joint=pan.name, tilt_joint=tilt.name)
    return Neck(unit, (), why, doubt)

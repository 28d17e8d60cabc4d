"""Print a drafted description as a Python module: ``description()`` with its reasons.

Each guessed field carries a ``# why:`` comment and, where the URDF left doubt, a
``# TODO doubt:`` comment. The text is laid out as ``ruff format`` would, so an edited
draft diffs cleanly against a fresh one.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from pathlib import Path

from robocram.robots.description import (
    DEFAULT_ALLOWED_CONTACTS,
    ArmDescription,
    CameraDescription,
    FrameSpec,
    PanTiltDescription,
    RobotDescription,
)
from robocram.robots.draft.source_writer import WIDTH, Call, Code, Item, call, quoted, render
from robocram.robots.errors import DescriptionError
from robocram.robots.example_robot_data import example_robot_data_folder
from robocram.robots.gripper import GripperDescription
from robocram.robots.model_additions import JointCoupling
from robocram.tf import Pose

_HEADER = '''"""{name}: a robot description drafted by `robocram robot draft` from {urdf}.

Check it with `robocram robot check {module}`; look at each `TODO doubt`.
"""

from __future__ import annotations

'''


class _Notes:
    def __init__(
        self, why: Mapping[str, str], doubts: Mapping[str, str], inferred: frozenset[str]
    ) -> None:
        self.why, self.doubts, self.inferred = why, doubts, inferred

    def item(self, path: str, key: str, value: object) -> Item:
        comments = []
        if path in self.why:
            comments.append(f"why: {self.why[path]}")
        if path in self.doubts:
            comments.append(f"TODO doubt: {self.doubts[path]}")
        return Item(key, value, tuple(comments))


def _pose(pose: Pose) -> Code:
    position = tuple(round(v, 6) + 0.0 for v in pose.position)
    orientation = tuple(round(v, 6) + 0.0 for v in pose.orientation)
    if orientation == (0.0, 0.0, 0.0, 1.0):
        return Code(f"Pose({position!r})")
    return Code(f"Pose({position!r}, {orientation!r})")


def _frame(spec: FrameSpec) -> object:
    return call("FrameSpec", name=spec.name, parent=spec.parent, pose=_pose(spec.pose))


def _coupling(spec: JointCoupling) -> object:
    extra = {} if spec.multiplier == 1.0 else {"multiplier": spec.multiplier}
    extra |= {} if spec.offset == 0.0 else {"offset": spec.offset}
    return call("JointCoupling", actuator=spec.actuator, followers=spec.followers, **extra)


def _arm(arm: ArmDescription, notes: _Notes) -> object:
    path = f"arms.{arm.name}"
    fields: list[Item] = [Item("name", arm.name)]
    for key in ("end_effector_link", "tool_frame", "base_link"):
        fields.append(notes.item(f"{path}.{key}", key, getattr(arm, key)))
    if arm.name not in notes.inferred:
        fields.append(notes.item(f"{path}.joints", "joints", arm.joints))
    if arm.gripper_joints:
        fields.append(notes.item(f"{path}.gripper_joints", "gripper_joints", arm.gripper_joints))
    fields.append(notes.item(f"{path}.parking", "parking", dict(arm.parking)))
    if arm.side is not None and arm.side != arm.name:
        fields.append(Item("side", arm.side))  # an arm called left is found by its name
    if arm.gripper is not None:
        fields.append(notes.item(f"{path}.gripper", "gripper", _gripper(arm.gripper)))
    return call("ArmDescription", *fields)


def _gripper(gripper: GripperDescription) -> object:
    if gripper.is_suction:
        return call("GripperDescription.suction")
    if gripper.curled_hand:
        return call("GripperDescription.curling")
    joints = tuple(
        call("GripperJoint", j.name, open=round(j.open, 6), closed=round(j.closed, 6))
        for j in gripper.joints
    )
    return call("GripperDescription", joints)


def _fov(value: float) -> object:
    """A field of view [rad]: whole degrees read as ``math.radians(d)``, else the number."""
    degrees = math.degrees(value)
    return (
        Code(f"math.radians({round(degrees)})") if abs(degrees - round(degrees)) < 1e-9 else value
    )


def _camera(camera: CameraDescription, notes: _Notes) -> object:
    """The camera without its heights: loading derives them from the URDF (said in a note)."""
    heights = ""
    if camera.minimal_height is not None and camera.maximal_height is not None:
        heights = (
            f"heights {camera.minimal_height:.3f} to {camera.maximal_height:.3f} m over the "
            "base (torso at its limits) are derived at load; give minimal_height and "
            "maximal_height to override"
        )
    frame = notes.item("cameras.0.frame", "frame", camera.frame)
    if heights:
        frame = Item(frame.key, frame.value, (*frame.comments, f"why: {heights}"))
    return call(
        "CameraDescription",
        frame,
        horizontal_fov=notes.item(
            "cameras.0.horizontal_fov", "horizontal_fov", _fov(camera.horizontal_fov)
        ),
        vertical_fov=_fov(camera.vertical_fov),
    )


def _pan_tilt(unit: PanTiltDescription) -> object:
    return call("PanTiltDescription", pan_joint=unit.pan_joint, tilt_joint=unit.tilt_joint)


def _urdf_code(urdf: Path, module_file: Path | None) -> str:
    """The ``URDF = ...`` expression."""
    try:
        inside = urdf.relative_to(example_robot_data_folder())
    except (ValueError, DescriptionError):
        inside = None
    if inside is not None:
        return f"example_robot_data_folder() / {quoted(inside.as_posix())}"
    if module_file is not None:
        relative = os.path.relpath(urdf, Path(module_file).resolve().parent)
        return f"Path(__file__).resolve().parent / {quoted(Path(relative).as_posix())}"
    return f"Path({quoted(urdf.as_posix())})"


def _body(desc: RobotDescription, notes: _Notes) -> object:
    fields = [Item("name", desc.name), Item("urdf", Code("URDF"))]
    fields.append(notes.item("base_frame", "base_frame", desc.base_frame))
    if desc.base_type is not None:
        fields.append(notes.item("base_type", "base_type", desc.base_type))
    if desc.torso_joint is not None:
        # its link, the joint's child, is derived at load
        fields.append(notes.item("torso_joint", "torso_joint", desc.torso_joint))
    arms = [
        notes.item(f"arms.{key}", quoted(key), _arm(arm, notes)) for key, arm in desc.arms.items()
    ]
    keyed = [Item(a.key, a.value, a.comments, dict_key=True) for a in arms]
    fields.append(notes.item("arms", "arms", Call("{", keyed, "}")))
    if desc.cameras:
        fields.append(notes.item("cameras.0", "cameras", (_camera(desc.cameras[0], notes),)))
    elif "cameras" in notes.doubts:  # the one line saying what to add
        fields.append(notes.item("cameras", "cameras", ()))
    if desc.pan_tilt is not None:
        fields.append(notes.item("pan_tilt", "pan_tilt", _pan_tilt(desc.pan_tilt)))
    if desc.neck_arm is not None:
        fields.append(notes.item("pan_tilt", "neck_arm", desc.neck_arm))
    if desc.neck_parking:
        fields.append(notes.item("neck_parking", "neck_parking", dict(desc.neck_parking)))
    if desc.stance:
        fields.append(notes.item("stance", "stance", dict(desc.stance)))
    if desc.extra_frames:
        fields.append(Item("extra_frames", tuple(_frame(f) for f in desc.extra_frames)))
    if desc.coupled_joints:
        couplings = tuple(_coupling(c) for c in desc.coupled_joints)
        fields.append(notes.item("coupled_joints", "coupled_joints", couplings))
    if desc.decomposed_links:
        fields.append(notes.item("decomposed_links", "decomposed_links", desc.decomposed_links))
    if desc.allowed_contacts != DEFAULT_ALLOWED_CONTACTS:
        fields.append(notes.item("allowed_contacts", "allowed_contacts", _contacts(desc)))
    return call("RobotDescription", *fields)


def _contacts(desc: RobotDescription) -> Call:
    """The allowed contacts as the defaults followed by the rules the draft adds."""
    default = len(DEFAULT_ALLOWED_CONTACTS)
    if desc.allowed_contacts[:default] != DEFAULT_ALLOWED_CONTACTS:
        return Call("(", [Item(None, rule) for rule in desc.allowed_contacts], ")")
    added = [Item(None, rule) for rule in desc.allowed_contacts[default:]]
    return Call("(", [Item(None, Code("*DEFAULT_ALLOWED_CONTACTS")), *added], ")")


def _import_line(module: str, names: list[str]) -> str:
    flat = f"from {module} import {', '.join(names)}"
    if len(flat) <= WIDTH:
        return flat + "\n"
    return f"from {module} import (\n" + "".join(f"    {n},\n" for n in names) + ")\n"


def draft_source(
    desc: RobotDescription,
    why: Mapping[str, str],
    doubts: Mapping[str, str],
    module_file: Path | None = None,
    inferred: frozenset[str] = frozenset(),
) -> str:
    """The module text for ``desc`` with ``why`` and ``doubts`` as comments.

    Arms named in ``inferred`` get no ``joints``: loading infers the same from the chain.
    """
    notes = _Notes(why, doubts, inferred)
    urdf = _urdf_code(Path(desc.urdf), module_file)
    data_folder = urdf.startswith("example_robot_data_folder")
    body = _body(desc, notes)
    names = [
        name
        for name, used in (
            ("ArmDescription", bool(desc.arms)),
            ("CameraDescription", bool(desc.cameras)),
            ("FrameSpec", bool(desc.extra_frames)),
            ("GripperDescription", any(a.gripper for a in desc.arms.values())),
            ("GripperJoint", any(a.gripper and a.gripper.joints for a in desc.arms.values())),
            ("JointCoupling", bool(desc.coupled_joints)),
            ("PanTiltDescription", desc.pan_tilt is not None),
            ("RobotDescription", True),
            ("example_robot_data_folder", data_folder),
        )
        if used
    ]
    module = module_file.name if module_file is not None else "THIS_FILE.py"
    text = _HEADER.format(name=desc.name, urdf=Path(desc.urdf).name, module=module)
    first, rest = text.split("\n", 1)
    if len(first) > WIDTH:  # a long robot or file name: ruff would refuse the line
        first = first.replace("` from ", "`\nfrom ", 1)
    text = f"{first}\n{rest}"
    uses_math = any("math." in repr(_fov(c.horizontal_fov)) for c in desc.cameras[:1])
    standard = ["import math"] if uses_math else []
    standard += ["from pathlib import Path"] if urdf.startswith("Path(") else []
    text += "".join(f"{line}\n" for line in standard) + ("\n" if standard else "")
    text += _import_line("robocram.robots", names)
    if "*DEFAULT_ALLOWED_CONTACTS" in repr(body):
        text += _import_line("robocram.robots.description", ["DEFAULT_ALLOWED_CONTACTS"])
    text += _import_line("robocram.tf", ["Pose"]) if desc.extra_frames else ""
    text += f"\nURDF = {urdf}\n\n\n"
    text += "def description() -> RobotDescription:\n"
    text += f'    """The {desc.name} description (unchecked; load_description checks it)."""\n'
    text += f"    return {render(body, '    ', len('return '))}\n"
    return text

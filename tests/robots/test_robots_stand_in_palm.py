"""A missing palm mesh's stand-in is a plate shaped from its finger row and thumb, and no
stand-in spans a child with no body (issue 37, zoo28).

Armar6's palm box spanned every child joint, its bodiless tool frame 7 cm before the palm
and its thumb's base 4.7 cm off it: 18.1 x 10.5 x 13.0 cm, 28 mm into the bowl its hand
held. The boxes are read back from raw PyBullet (the written URDF loaded on its own), the
rule's figures from the URDF's joint origins parsed here.
"""

from __future__ import annotations

import math
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pybullet as p
import pytest

from robocram.robot_check import check_robot, description_from
from robocram.robots import RobotModel
from tests.drafts import drafted_module

ARMAR6 = Path(__file__).resolve().parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"
TOLERANCE = 0.001  # [m]
THICKNESS_SHARE = 0.25  # the rule: a box is this share of the link's length thick

FINGERS = ((0.09, -0.03), (0.092, -0.01), (0.09, 0.01), (0.085, 0.03))  # (x, z) [m]
THUMB = (0.04, -0.04, -0.035)  # [m] off the palm's plane, on its inner side
TOOL = (0.1, -0.06, 0.0)  # [m] a bare frame where a held thing lies
WRIST = 0.1  # [m] the palm's frame from the arm's


def _mesh_link(name: str) -> str:
    mesh = f'<geometry><mesh filename="meshes/{name}.stl"/></geometry>'
    return f'<link name="{name}"><visual>{mesh}</visual><collision>{mesh}</collision></link>'


def _joint(name: str, parent: str, child: str, xyz: tuple[float, ...], kind: str) -> str:
    limit = '<axis xyz="1 0 0"/><limit lower="0" upper="1.5" effort="1" velocity="1"/>'
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{" ".join(str(v) for v in xyz)}"/>{limit if kind != "fixed" else ""}'
        "</joint>"
    )


def _turned(xyz: tuple[float, float, float], turn: float) -> tuple[float, float, float]:
    """``xyz`` turned by ``turn`` [rad] about z."""
    c, s = math.cos(turn), math.sin(turn)
    return (c * xyz[0] - s * xyz[1], s * xyz[0] + c * xyz[1], xyz[2])


def _hand_urdf(thumb: bool = True, turn: float = 0.0, links: int = 2) -> str:
    """An arm, a palm on a wrist joint, four fingers in a row, a thumb (``thumb``), each of
    ``links`` links, and a bare tool frame, the palm's children turned ``turn`` [rad] about
    its z; no mesh file exists."""
    tool = _joint("tool_joint", "palm", "tool", _turned(TOOL, turn), "fixed")
    parts = ['<robot name="hand">', '<link name="arm"><visual><geometry>',
             '<box size="0.05 0.05 0.05"/></geometry></visual></link>', _mesh_link("palm"),
             _joint("wrist", "arm", "palm", (0.0, 0.0, WRIST), "revolute"),
             '<link name="tool"/>', tool]  # fmt: skip
    chains = [(f"f{k}", (x, 0.0, z)) for k, (x, z) in enumerate(FINGERS)]
    if thumb:
        chains.append(("thumb", THUMB))
    for name, at in chains:
        parts.append(_mesh_link(f"{name}_1"))
        parts.append(_joint(f"{name}_base", "palm", f"{name}_1", _turned(at, turn), "revolute"))
        if links > 1:
            parts.append(_mesh_link(f"{name}_2"))
            parts.append(_joint(f"{name}_mid", f"{name}_1", f"{name}_2", (0.04, 0, 0), "revolute"))
    return "\n".join([*parts, "</robot>"])


def _origins(urdf: str, parent: str) -> dict[str, tuple[float, float, float]]:
    """The origins [m] of ``parent``'s child joints, by child link, parsed here."""
    found = {}
    for joint in ET.fromstring(urdf).iter("joint"):
        if joint.find("parent").attrib["link"] == parent:  # type: ignore[union-attr]
            xyz = joint.find("origin").attrib["xyz"].split()  # type: ignore[union-attr]
            x, y, z = (float(v) for v in xyz)
            found[joint.find("child").attrib["link"]] = (x, y, z)  # type: ignore[union-attr]
    return found


def _box_in_pybullet(model: RobotModel, link: str, tmp_path: Path) -> tuple[list[float], ...]:
    """``link``'s collision box as raw PyBullet loads the written URDF, every joint at 0:
    its low and high corners [m] in the link's frame (the box's axes turned onto it)."""
    path = tmp_path / f"{model.name}.urdf"
    model.to_urdf(path)
    client = p.connect(p.DIRECT)
    try:
        body = p.loadURDF(str(path), useFixedBase=True, physicsClientId=client)
        index = next(
            i
            for i in range(p.getNumJoints(body, physicsClientId=client))
            if p.getJointInfo(body, i, physicsClientId=client)[12].decode() == link
        )
        state = p.getLinkState(body, index, physicsClientId=client)
        shape = p.getCollisionShapeData(body, index, physicsClientId=client)[0]
        assert shape[2] == p.GEOM_BOX
        box = p.multiplyTransforms(state[0], state[1], shape[5], shape[6])  # from the CoM
        to_link = p.invertTransform(state[4], state[5])
        centre, turn = p.multiplyTransforms(*to_link, *box)
        rows = np.abs(np.reshape(p.getMatrixFromQuaternion(turn), (3, 3)))
        half = rows @ (np.asarray(shape[3]) / 2)  # extents in the link's axes
        return list(np.subtract(centre, half)), list(np.add(centre, half))
    finally:
        p.disconnect(client)


def _model(urdf: str, tmp_path: Path) -> RobotModel:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the missing meshes
        return RobotModel.from_string(urdf, base_dir=tmp_path)


def test_a_palms_box_is_a_plate_over_its_finger_row_and_thumb(tmp_path: Path) -> None:
    """The plate lies in the plane through the wrist's frame and the finger row (here
    y = 0), spans them and the thumb's base as it lies on that plane, and is as thick as
    a quarter of the wrist's offset; the bare tool frame 6 cm off it is not spanned."""
    urdf = _hand_urdf()
    children = _origins(urdf, "palm")
    bases = [children[f"f{k}_1"] for k in range(len(FINGERS))]
    x, _, z = children["thumb_1"]
    spanned = [(0.0, 0.0, 0.0), *bases, (x, 0.0, z)]  # the thumb's base on the plate
    thickness = THICKNESS_SHARE * WRIST
    low, high = _box_in_pybullet(_model(urdf, tmp_path), "palm", tmp_path)
    for axis in (0, 2):
        least = min(s[axis] for s in spanned) - thickness / 2
        most = max(s[axis] for s in spanned) + thickness / 2
        assert low[axis] == pytest.approx(least, abs=TOLERANCE)
        assert high[axis] == pytest.approx(most, abs=TOLERANCE)
    assert low[1] == pytest.approx(-thickness / 2, abs=TOLERANCE)
    assert high[1] == pytest.approx(thickness / 2, abs=TOLERANCE)
    assert low[1] > children["tool"][1] + 0.04  # the tool frame lies well outside it


@pytest.mark.parametrize(("thumb", "links"), [(False, 2), (True, 1)])
def test_no_thumb_or_no_finger_chains_keep_the_box_over_the_joints(
    tmp_path: Path, thumb: bool, links: int
) -> None:
    """No thumb off the row (a parallel gripper's knuckles lie in one), or children of one
    link each (a base's wheels and a mast): no plate, the box spans the link's frame and
    its children with a body, the bare frame left out."""
    urdf = _hand_urdf(thumb=thumb, links=links)
    children = _origins(urdf, "palm")
    spanned = [(0.0, 0.0, 0.0), *(o for c, o in children.items() if c != "tool")]
    thickness = THICKNESS_SHARE * WRIST
    low, high = _box_in_pybullet(_model(urdf, tmp_path), "palm", tmp_path)
    for axis in range(3):
        least = min(s[axis] for s in spanned) - thickness / 2
        assert low[axis] == pytest.approx(least, abs=TOLERANCE)
        assert high[axis] == pytest.approx(
            max(s[axis] for s in spanned) + thickness / 2, abs=TOLERANCE
        )


def test_a_link_whose_children_are_all_frames_still_spans_them(tmp_path: Path) -> None:
    """A head whose children are camera frames only (Armar6's ``upper_neck``): the frames
    tell its size, so its box still reaches them."""
    camera = (0.03, 0.2, 0.15)
    urdf = "\n".join([
        '<robot name="head">', '<link name="neck"><visual><geometry>',
        '<box size="0.05 0.05 0.05"/></geometry></visual></link>', _mesh_link("head"),
        _joint("pan", "neck", "head", (0.0, 0.0, 0.2), "revolute"),
        '<link name="camera"/>', _joint("camera_joint", "head", "camera", camera, "fixed"),
        "</robot>",
    ])  # fmt: skip
    low, high = _box_in_pybullet(_model(urdf, tmp_path), "head", tmp_path)
    thickness = THICKNESS_SHARE * 0.2
    for axis in range(3):
        assert low[axis] == pytest.approx(min(0.0, camera[axis]) - thickness / 2, abs=TOLERANCE)
        assert high[axis] == pytest.approx(max(0.0, camera[axis]) + thickness / 2, abs=TOLERANCE)


def test_armar6s_palm_is_a_plate_and_its_robot_check_still_passes(tmp_path: Path) -> None:
    """Armar6's palm plate is 3.5 cm thick (its box was 10.5 cm, out to the tool frame),
    and its draft passes every check, as it did."""
    urdf = ARMAR6.read_text("utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = RobotModel.from_file(ARMAR6, missing_packages_as_boxes=True)
        module = tmp_path / "armar6.py"
        drafted_module(ARMAR6, module)
        card = check_robot(description_from(str(module)))
    low, high = _box_in_pybullet(model, "Hand R Palm", tmp_path)
    wrist = _origins(urdf, "arm_t8_r1")["Hand R Palm"]
    thickness = THICKNESS_SHARE * sum(v * v for v in wrist) ** 0.5
    assert high[1] - low[1] == pytest.approx(thickness, abs=TOLERANCE)
    tool = _origins(urdf, "Hand R Palm")["right_tool_frame"]
    assert low[1] > tool[1] + 0.04
    assert card.passed, [f"{f.name}: {f.detail}" for f in card.failures()]


def test_a_turned_palm_gets_a_turned_plate(tmp_path: Path) -> None:
    """The same hand, its fingers and thumb turned 0.5 rad about the palm's z: the plate
    turns with them (its thin side along the turned normal), the same size."""
    turn = 0.5
    model = _model(_hand_urdf(turn=turn), tmp_path)
    path = tmp_path / "turned.urdf"
    model.to_urdf(path)
    client = p.connect(p.DIRECT)
    try:
        body = p.loadURDF(str(path), useFixedBase=True, physicsClientId=client)
        index = next(
            i
            for i in range(p.getNumJoints(body, physicsClientId=client))
            if p.getJointInfo(body, i, physicsClientId=client)[12].decode() == "palm"
        )
        state = p.getLinkState(body, index, physicsClientId=client)
        shape = p.getCollisionShapeData(body, index, physicsClientId=client)[0]
        box = p.multiplyTransforms(state[0], state[1], shape[5], shape[6])
        _, orientation = p.multiplyTransforms(*p.invertTransform(state[4], state[5]), *box)
        axes = np.reshape(p.getMatrixFromQuaternion(orientation), (3, 3))  # columns: box axes
    finally:
        p.disconnect(client)
    low, high = _box_in_pybullet(_model(_hand_urdf(), tmp_path), "palm", tmp_path)
    assert sorted(shape[3]) == pytest.approx(sorted(np.subtract(high, low)), abs=TOLERANCE)
    thin = axes[:, int(np.argmin(shape[3]))]
    normal = _turned((0.0, 1.0, 0.0), turn)
    assert abs(float(np.dot(thin, normal))) == pytest.approx(1.0, abs=1e-6)

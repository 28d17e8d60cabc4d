"""Property tests of URDF reading: random trees round-trip and agree with pinocchio;
random spoilings always end in a typed UrdfError.

The example count is small in ``make test``; ``ROBOCRAM_PROPERTY_EXAMPLES=2000 make test``
(or any number) runs the long search. The quick run is derandomised so CI is repeatable.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, replace

import numpy as np
import pinocchio as pin
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robocram.robots import RobotModel, UrdfError
from robocram.tf import Pose
from robocram.tf import quaternion as quat

EXAMPLES = int(os.environ.get("ROBOCRAM_PROPERTY_EXAMPLES", "20"))
PROPERTY_SETTINGS = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize="ROBOCRAM_PROPERTY_EXAMPLES" not in os.environ,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
KINDS = ("revolute", "continuous", "prismatic", "fixed")


@dataclass(frozen=True)
class JointSpec:
    """One joint of a generated tree (link ``i + 1`` hangs from link ``parent``)."""

    kind: str
    parent: int
    xyz: tuple[float, float, float]
    rpy: tuple[float, float, float]
    axis: tuple[float, float, float]
    lower: float
    upper: float


coordinate = st.floats(-1.0, 1.0, allow_nan=False).map(lambda v: round(v, 6))
angle = st.floats(-math.pi + 1e-3, math.pi - 1e-3, allow_nan=False).map(lambda v: round(v, 6))
pitch = st.floats(-1.5, 1.5, allow_nan=False).map(lambda v: round(v, 6))


@st.composite
def unit_axes(draw: st.DrawFn) -> tuple[float, float, float]:
    """A unit axis, written with enough digits to stay unit after reading."""
    x, y, z = (draw(st.floats(-1.0, 1.0)) for _ in range(3))
    norm = math.sqrt(x * x + y * y + z * z)
    if norm < 0.1:
        return (0.0, 0.0, 1.0)
    return (x / norm, y / norm, z / norm)


@st.composite
def trees(draw: st.DrawFn) -> list[JointSpec]:
    """Joints of a random tree with 1 to 7 joints below link 0."""
    count = draw(st.integers(1, 7))
    joints = []
    for i in range(count):
        low = draw(st.floats(-3.0, 3.0).map(lambda v: round(v, 6)))
        span = draw(st.floats(0.0, 3.0).map(lambda v: round(v, 6)))
        joints.append(
            JointSpec(
                kind=draw(st.sampled_from(KINDS)),
                parent=draw(st.integers(0, i)),
                xyz=(draw(coordinate), draw(coordinate), draw(coordinate)),
                rpy=(draw(angle), draw(pitch), draw(angle)),
                axis=draw(unit_axes()),
                lower=low,
                upper=round(low + span, 6),
            )
        )
    return joints


def joint_xml(index: int, spec: JointSpec, parent: int | None = None) -> str:
    """The ``<joint>`` of link ``index + 1`` (``parent`` overrides the spec's)."""
    limit = (
        f'<limit lower="{spec.lower!r}" upper="{spec.upper!r}" effort="10" velocity="1"/>'
        if spec.kind in ("revolute", "prismatic")
        else ""
    )
    axis = " ".join(repr(a) for a in spec.axis)
    return (
        f'<joint name="j{index + 1}" type="{spec.kind}">'
        f'<parent link="l{spec.parent if parent is None else parent}"/>'
        f'<child link="l{index + 1}"/>'
        f'<origin xyz="{" ".join(map(repr, spec.xyz))}" rpy="{" ".join(map(repr, spec.rpy))}"/>'
        f'<axis xyz="{axis}"/>{limit}</joint>'
    )


def tree_xml(joints: list[JointSpec], skip_link: int | None = None) -> str:
    """URDF text of a generated tree; ``skip_link`` leaves that link's element out."""
    links = "\n".join(f'<link name="l{i}"/>' for i in range(len(joints) + 1) if i != skip_link)
    body = "\n".join(joint_xml(i, j) for i, j in enumerate(joints))
    return f'<robot name="random">\n{links}\n{body}\n</robot>'


def _motion(kind: str, axis: tuple[float, float, float], q: float) -> Pose:
    if kind in ("revolute", "continuous"):
        return Pose(orientation=quat.from_axis_angle(axis, q))
    if kind == "prismatic":
        return Pose((axis[0] * q, axis[1] * q, axis[2] * q))
    return Pose()


def _our_fk(model: RobotModel, values: dict[str, float]) -> dict[str, Pose]:
    """Each link's pose in the root, composed from the model's joints (parents first)."""
    poses = {model.root_link: Pose()}
    for joint in model.joints.values():  # generated parents come before children
        motion = _motion(joint.type, joint.axis, values.get(joint.name, 0.0))
        poses[joint.child] = poses[joint.parent] * joint.origin * motion
    return poses


def _values(joints: list[JointSpec], share: float) -> dict[str, float]:
    return {
        f"j{i + 1}": j.lower + share * (j.upper - j.lower) if j.kind != "continuous" else share
        for i, j in enumerate(joints)
        if j.kind != "fixed"
    }


@PROPERTY_SETTINGS
@given(joints=trees(), share=st.floats(0.0, 1.0))
def test_random_trees_round_trip_and_agree_with_pinocchio(
    joints: list[JointSpec], share: float
) -> None:
    xml = tree_xml(joints)
    model = RobotModel.from_string(xml)
    again = RobotModel.from_string(model.to_urdf())
    assert list(again.joints) == list(model.joints) and list(again.links) == list(model.links)
    for name, joint in model.joints.items():
        other = again.joints[name]
        assert (other.type, other.parent, other.child) == (joint.type, joint.parent, joint.child)
        assert (other.lower, other.upper) == (joint.lower, joint.upper)
        assert np.allclose(other.origin.matrix(), joint.origin.matrix(), atol=1e-9)
    pin_model = pin.buildModelFromXML(xml)
    movable = [f"j{i + 1}" for i, j in enumerate(joints) if j.kind != "fixed"]
    assert sorted(pin_model.names[1:]) == sorted(movable)  # pinocchio orders depth-first
    for i, spec in enumerate(joints):
        if spec.kind in ("revolute", "prismatic"):
            jid = pin_model.getJointId(f"j{i + 1}")
            q_index = pin_model.joints[jid].idx_q
            assert pin_model.lowerPositionLimit[q_index] == pytest.approx(spec.lower, abs=1e-9)
            assert pin_model.upperPositionLimit[q_index] == pytest.approx(spec.upper, abs=1e-9)
    values = _values(joints, share)
    q = pin.neutral(pin_model)
    for name, value in values.items():
        joint = pin_model.joints[pin_model.getJointId(name)]
        if joint.nq == 2:  # continuous joints are (cos, sin) in pinocchio
            q[joint.idx_q : joint.idx_q + 2] = (math.cos(value), math.sin(value))
        else:
            q[joint.idx_q] = value
    data = pin_model.createData()
    pin.framesForwardKinematics(pin_model, data, q)
    for link, ours in _our_fk(again, values).items():
        theirs = data.oMf[pin_model.getFrameId(link)]
        assert np.allclose(ours.matrix(), theirs.homogeneous, atol=1e-9), link


@st.composite
def spoiled(draw: st.DrawFn) -> str:
    """A generated tree with one fault: a missing link, a loop, or a bad number."""
    joints = draw(trees())
    fault = draw(st.sampled_from(("missing link", "loop", "number")))
    if fault == "missing link":
        return tree_xml(joints, skip_link=draw(st.integers(0, len(joints))))
    if fault == "loop":  # hang a joint's parent below its own child
        i = draw(st.integers(0, len(joints) - 1))
        below = _descendants(joints, i + 1)
        parent = draw(st.sampled_from(sorted(below)))
        xml = tree_xml(joints)
        return xml.replace(joint_xml(i, joints[i]), joint_xml(i, joints[i], parent))
    i = draw(st.integers(0, len(joints) - 1))
    bad = draw(
        st.sampled_from(
            ('lower="nan"', 'upper="inf"', 'lower="x"', 'effort="-1"', "lower-upper", "axis")
        )
    )
    spec = replace(joints[i], kind="revolute")
    good = joint_xml(i, spec)
    if bad == "lower-upper":
        spoilt = joint_xml(i, replace(spec, lower=spec.upper + 1.0))
    elif bad == "axis":
        spoilt = joint_xml(i, replace(spec, axis=(0.0, 0.0, 0.0)))
    else:
        key = bad.split("=")[0]
        spoilt = re.sub(rf'{key}="[^"]*"', bad, good, count=1)
    return tree_xml(joints).replace(joint_xml(i, joints[i]), spoilt)


def _descendants(joints: list[JointSpec], link: int) -> set[int]:
    found = {link}
    for i, joint in enumerate(joints):  # parents come before children
        if joint.parent in found:
            found.add(i + 1)
    return found


@PROPERTY_SETTINGS
@given(xml=spoiled())
def test_spoiled_trees_always_give_a_urdf_error(xml: str) -> None:
    with pytest.raises(UrdfError):
        RobotModel.from_string(xml)

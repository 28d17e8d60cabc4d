"""Bad URDFs end in a typed UrdfError naming the file, the line and the culprit (issue 11).

Each case here was accepted or crashed before: a loop next to a root made ``chain`` loop
forever, crossed limits clamped every value to the upper one, ``package://../..`` read
outside the package, a Latin-1 file raised a raw UnicodeDecodeError.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.robots import PackagePathError, RobotModel, UrdfError

JOINT = """<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>
  {extra}</joint>"""


def _robot(links: str, *joints: str) -> str:
    body = "".join(f'<link name="{n}"/>' for n in links.split())
    return f'<robot name="r">{body}\n' + "\n".join(joints) + "</robot>"


def _joint(name: str, parent: str, child: str, kind: str = "fixed", extra: str = "") -> str:
    return JOINT.format(name=name, kind=kind, parent=parent, child=child, extra=extra)


def test_a_loop_beside_a_root_names_the_joints_that_close_it() -> None:
    xml = _robot("root a b", _joint("ab", "a", "b"), _joint("ba", "b", "a"))
    with pytest.raises(UrdfError, match=r"joints 'ab', 'ba' close a kinematic loop") as info:
        RobotModel.from_string(xml)
    assert "a -> b -> a" in str(info.value)


def test_a_loop_with_no_root_says_loop_not_found_no_root() -> None:
    xml = _robot("a b c", _joint("ab", "a", "b"), _joint("bc", "b", "c"), _joint("ca", "c", "a"))
    with pytest.raises(UrdfError, match=r"close a kinematic loop") as info:
        RobotModel.from_string(xml)
    assert "found []" not in str(info.value)
    assert all(repr(j) in str(info.value) for j in ("ab", "bc", "ca"))


LIMITED = _robot("a b", _joint("j", "a", "b", "revolute", '<axis xyz="{axis}"/>\n  {limit}'))


@pytest.mark.parametrize(
    ("limit", "axis", "message", "line"),
    [  # the <axis> is on line 3 of the file, the <limit> on line 4
        ('<limit lower="1" upper="-1"/>', "0 0 1", r"lower limit 1.0 > upper -1.0", 4),
        ('<limit lower="nan" upper="1"/>', "0 0 1", r"lower='nan' is not finite", 4),
        ('<limit lower="-1" upper="inf"/>', "0 0 1", r"upper='inf' is not finite", 4),
        ('<limit lower="-1" upper="1" effort="-5"/>', "0 0 1", r"negative effort -5.0", 4),
        ('<limit lower="-1" upper="1" velocity="-2"/>', "0 0 1", r"negative velocity -2.0", 4),
        ('<limit lower="-1" upper="1"/>', "0 0 0", r"joint 'j' has a zero axis", 3),
        ('<limit lower="-1" upper="1"/>', "nan 0 1", r"xyz='nan 0 1' is not finite", 3),
    ],
)
def test_bad_joint_numbers_are_refused_with_file_and_line(
    tmp_path: Path, limit: str, axis: str, message: str, line: int
) -> None:
    urdf = tmp_path / "bad.urdf"
    urdf.write_text(LIMITED.format(limit=limit, axis=axis), encoding="utf-8")
    with pytest.raises(UrdfError, match=message) as info:
        RobotModel.from_file(urdf)
    assert info.value.source == str(urdf) and info.value.line == line


@pytest.mark.parametrize(
    "uri",
    [
        "package://../../etc/passwd",
        "package://tiny_pkg/../../../etc/passwd",
        "package://tiny_pkg//etc/passwd",
        "package://./meshes/body.stl",
        "package:///../etc/passwd",
        "package:///",
    ],
)
def test_package_paths_stay_inside_the_package(tiny_package: Path, uri: str) -> None:
    xml = f'<robot name="r"><link name="a"><visual><geometry><mesh filename="{uri}"/>'
    xml += "</geometry></visual></link></robot>"
    with pytest.raises(PackagePathError, match="refusing") as info:
        RobotModel.from_string(xml, package_paths=[tiny_package])
    assert info.value.uri == uri


def test_a_path_that_comes_back_inside_the_package_is_fine(tiny_package: Path) -> None:
    uri = "package://tiny_pkg/meshes/../meshes/body.stl"
    xml = f'<robot name="r"><link name="a"><visual><geometry><mesh filename="{uri}"/>'
    xml += "</geometry></visual></link></robot>"
    model = RobotModel.from_string(xml, package_paths=[tiny_package])
    assert Path(model.links["a"].visuals[0].geometry.filename).resolve() == (
        tiny_package / "tiny_pkg" / "meshes" / "body.stl"
    )


def test_a_latin1_file_with_its_declaration_reads(tmp_path: Path) -> None:
    urdf = tmp_path / "latin.urdf"
    text = '<?xml version="1.0" encoding="ISO-8859-1"?>\n<robot name="bär"><link name="é"/></robot>'
    urdf.write_bytes(text.encode("latin-1"))
    model = RobotModel.from_file(urdf)
    assert (model.name, model.root_link) == ("bär", "é")


def test_undeclared_latin1_names_the_line_and_the_fix(tmp_path: Path) -> None:
    urdf = tmp_path / "latin.urdf"
    urdf.write_bytes('<robot name="r">\n<link name="é"/></robot>'.encode("latin-1"))
    with pytest.raises(UrdfError, match=r"byte 0xe9 is not utf-8; declare") as info:
        RobotModel.from_file(urdf)
    assert info.value.line == 2


def test_an_unknown_declared_encoding_is_a_urdf_error(tmp_path: Path) -> None:
    urdf = tmp_path / "odd.urdf"
    urdf.write_bytes(b'<?xml version="1.0" encoding="klingon-8"?>\n<robot name="r"/>')
    with pytest.raises(UrdfError, match="unknown encoding 'klingon-8'"):
        RobotModel.from_file(urdf)

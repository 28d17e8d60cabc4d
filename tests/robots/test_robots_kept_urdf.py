"""A URDF's parts come from disk only while its mesh references find what they found.

Each test has its own cache folder; whether a parse ran is counted at the reader, and the
parts are compared with a parse of the same text by ``read_urdf`` itself.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

import robocram.robots.kept_urdf as kept_urdf
from robocram.robots import MissingMeshWarning, RobotModel
from robocram.robots.package_resolver import PackageResolver
from robocram.robots.safe_xml import parse_xml
from robocram.robots.urdf_reader import UrdfParts, read_urdf

_URDF = """<robot name="r">
  <link name="base"><collision><geometry><mesh filename="part.stl"/></geometry></collision></link>
  <link name="arm"><collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""
_STL = "solid p\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n" \
    "endloop\nendfacet\nendsolid p\n"  # fmt: skip


@pytest.fixture
def reads(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The sources parsed (not read from disk), with the cache in ``tmp_path/cache``."""
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path / "cache"))
    parsed: list[str] = []

    def counted(*args: object, **kwargs: object) -> UrdfParts:
        parsed.append(str(args[1]))
        return read_urdf(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(kept_urdf, "read_urdf", counted)
    return parsed


def _parts(file: Path) -> UrdfParts:
    text = file.read_text()
    resolver = PackageResolver.default(())
    return kept_urdf.kept_urdf_parts(text, str(file), file.parent, resolver)


def test_a_second_read_is_the_parse_from_disk(tmp_path: Path, reads: list[str]) -> None:
    file = tmp_path / "r.urdf"
    file.write_text(_URDF)
    (tmp_path / "part.stl").write_text(_STL)
    first, second = _parts(file), _parts(file)
    assert reads == [str(file)]
    direct = read_urdf(parse_xml(_URDF, str(file)), str(file), tmp_path, PackageResolver.default())
    assert first == direct and second == direct and second is not first
    mesh = second.links["base"].collisions[0].geometry
    assert mesh.kind == "mesh" and mesh.filename == str(tmp_path / "part.stl")


def test_a_mesh_that_comes_or_goes_is_read_anew(tmp_path: Path, reads: list[str]) -> None:
    file = tmp_path / "r.urdf"
    file.write_text(_URDF)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        missing = RobotModel.from_file(file)
    assert [w.category for w in caught] == [MissingMeshWarning]
    assert missing.links["base"].collisions[0].geometry.kind == "box"
    del missing  # the model memo holds models weakly: the next load reads the file again
    (tmp_path / "part.stl").write_text(_STL)
    found = _parts(file)
    assert found.links["base"].collisions[0].geometry.kind == "mesh" and len(reads) == 2
    (tmp_path / "part.stl").unlink()
    assert _parts(file).links["base"].collisions[0].geometry.kind == "box" and len(reads) == 3
    assert _parts(file).missing_meshes == ["part.stl"] and len(reads) == 3  # kept again

"""Mesh references at the URDF door: mesh files only, and no climbing out of the package
(issue 42, weak: a mesh path ``../../../../etc/passwd`` was accepted by the draft)."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.robots import PackagePathError, RobotModel, UrdfError
from robocram.scenes import draft_environment


def _urdf(folder: Path, mesh: str) -> Path:
    path = folder / "thing.urdf"
    path.write_text(
        '<robot name="thing"><link name="base"><collision><geometry>'
        f'<mesh filename="{mesh}"/></geometry></collision></link></robot>',
        "utf-8",
    )
    return path


def test_a_path_to_no_mesh_file_is_refused_naming_it(tmp_path: Path) -> None:
    urdf = _urdf(tmp_path, "../../../../etc/passwd")
    with pytest.raises(UrdfError, match=r"mesh '\.\./\.\./\.\./\.\./etc/passwd' is no mesh file"):
        RobotModel.from_file(urdf)
    with pytest.raises(UrdfError, match="is no mesh file"):
        draft_environment(urdf)


def test_a_relative_mesh_climbing_out_of_its_package_is_refused(tmp_path: Path) -> None:
    package = tmp_path / "thing_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text("<package/>", "utf-8")
    (tmp_path / "secret.stl").write_text("solid x\nendsolid x\n", "utf-8")
    with pytest.raises(PackagePathError, match=r"leaves the folder of 'thing_description'"):
        RobotModel.from_file(_urdf(package / "urdf", "../../secret.stl"))


def test_a_relative_mesh_inside_its_package_is_read(tmp_path: Path) -> None:
    package = tmp_path / "thing_description"
    (package / "urdf").mkdir(parents=True)
    (package / "meshes").mkdir()
    (package / "package.xml").write_text("<package/>", "utf-8")
    mesh = package / "meshes" / "base.STL"
    mesh.write_text("solid x\nendsolid x\n", "utf-8")
    model = RobotModel.from_file(_urdf(package / "urdf", "../meshes/base.STL"))
    assert model.links["base"].collisions[0].geometry.filename == str(mesh.resolve())

"""package:// resolution from user folders, ROS_PACKAGE_PATH and installed prefixes."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.robots import PackageNotFoundError, RobotModel
from robocram.robots.example_robot_data import example_robot_data_folder
from robocram.robots.package_resolver import PackageResolver

OUTSIDE_URDF = """<robot name="outside"><link name="base">
  <visual><geometry><mesh filename="package://tiny_pkg/meshes/body.stl"/></geometry></visual>
</link></robot>"""


def test_user_folder_resolves_a_package(tiny_package: Path) -> None:
    model = RobotModel.from_string(OUTSIDE_URDF, package_paths=[tiny_package])
    mesh = model.links["base"].visuals[0].geometry
    assert mesh.filename == str(tiny_package / "tiny_pkg" / "meshes" / "body.stl")


def test_ros_package_path_resolves_a_package(
    tiny_package: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ROS_PACKAGE_PATH", f"{tmp_path / 'nothing_here'}:{tiny_package}")
    model = RobotModel.from_string(OUTSIDE_URDF)
    assert model.links["base"].visuals[0].geometry.filename.endswith("tiny_pkg/meshes/body.stl")


def test_user_folder_wins_over_ros_package_path(
    tiny_package: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    other = tmp_path / "other"
    (other / "tiny_pkg" / "meshes").mkdir(parents=True)
    (other / "tiny_pkg" / "meshes" / "body.stl").write_text("solid x\nendsolid x\n")
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(tiny_package))
    resolver = PackageResolver.default([other])
    assert resolver.resolve("package://tiny_pkg/meshes/body.stl") == (
        other.resolve() / "tiny_pkg" / "meshes" / "body.stl"
    )


def test_unknown_package_names_uri_and_searched_folders(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    with pytest.raises(PackageNotFoundError) as info:
        RobotModel.from_string(OUTSIDE_URDF, package_paths=[tmp_path])
    err = info.value
    assert err.package == "tiny_pkg"
    assert err.uri == "package://tiny_pkg/meshes/body.stl"
    assert tmp_path.resolve() in err.searched
    assert "ROS_PACKAGE_PATH" in str(err)


def test_installed_example_robot_data_is_found() -> None:
    resolver = PackageResolver.default()
    uri = "package://example-robot-data/robots/pr2_description/urdf/pr2.urdf"
    assert resolver.resolve(uri) == example_robot_data_folder() / "pr2_description/urdf/pr2.urdf"
    assert resolver.resolve(uri).is_file()


def test_relative_and_file_uris(tmp_path: Path) -> None:
    resolver = PackageResolver(())
    assert resolver.resolve("meshes/a.stl", tmp_path) == (tmp_path / "meshes" / "a.stl").resolve()
    assert resolver.resolve("file:///abs/b.stl") == Path("/abs/b.stl")


def test_an_empty_package_segment_reads_as_pinocchio_reads_it(tiny_package: Path) -> None:
    """``package:///pkg/...`` (TALOS's meshes) resolves to ``package://pkg/...``."""
    resolver = PackageResolver.default([tiny_package])
    mesh = tiny_package / "tiny_pkg" / "meshes" / "body.stl"
    assert resolver.resolve("package:///tiny_pkg/meshes/body.stl") == mesh
    assert resolver.resolve("package://tiny_pkg/meshes/body.stl") == mesh


def test_talos_loads_with_its_meshes() -> None:
    urdf = example_robot_data_folder() / "talos_data" / "robots" / "talos_left_arm.urdf"
    model = RobotModel.from_file(urdf)
    meshes = [
        Path(v.geometry.filename)
        for link in model.links.values()
        for v in link.visuals
        if v.geometry.kind == "mesh"
    ]
    assert meshes and all(m.is_file() for m in meshes)
    assert all("talos_data/meshes" in m.as_posix() for m in meshes)

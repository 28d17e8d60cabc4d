"""An environment's meshes are found wherever a user keeps them, and its surfaces are
measured on them (issue 37, item 2): ``--package-path`` (``package_paths``),
``ROS_PACKAGE_PATH``, a package beside the URDF, a relative path.

The issue's kitchen had a dining table mesh of 1.28 x 0.80 x 0.79 m drafted as a
0.6 x 0.6 m stand-in at 0.37 m, and no table surface once its meshes were found.
"""

from __future__ import annotations

import struct
from pathlib import Path

import pybullet
import pytest

from robocram.cli import main
from robocram.scenes import draft_environment
from robocram.scenes.environment_model import loadable_urdf
from robocram.world import World

TABLE = (1.28, 0.80, 0.79)  # [m] the mesh's extents; its top at 0.79 m
URDF = """<robot name="dining">
  <link name="room"/>
  <link name="dining_table"><collision><geometry><mesh filename="{uri}"/></geometry></collision>
    <visual><geometry><mesh filename="{uri}"/></geometry></visual></link>
  <joint name="table_joint" type="fixed"><parent link="room"/><child link="dining_table"/>
    <origin xyz="1 0 0"/></joint>
</robot>"""


def _box_stl(path: Path, size: tuple[float, float, float]) -> None:
    """A binary STL of a box standing on z = 0, centred in x and y."""
    sx, sy, sz = size[0] / 2, size[1] / 2, size[2]
    corners = [(x, y, z) for x in (-sx, sx) for y in (-sy, sy) for z in (0.0, sz)]
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]  # fmt: skip
    data = bytearray(80) + struct.pack("<I", len(faces))
    for face in faces:
        data += struct.pack("<3f", 0.0, 0.0, 0.0)
        for index in face:
            data += struct.pack("<3f", *corners[index])
        data += struct.pack("<H", 0)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(bytes(data))


def _kitchen(folder: Path, uri: str, package_at: Path, package: str = "dining_meshes") -> Path:
    (package_at / package).mkdir(parents=True, exist_ok=True)
    (package_at / package / "package.xml").write_text("<package/>", "utf-8")
    _box_stl(package_at / package / "meshes" / "table.stl", TABLE)
    folder.mkdir(parents=True, exist_ok=True)
    urdf = folder / "dining.urdf"
    urdf.write_text(URDF.format(uri=uri), "utf-8")
    return urdf


def _table_surface(urdf: Path, **kwargs: object) -> tuple[float, bool]:
    draft = draft_environment(urdf, **kwargs)  # type: ignore[arg-type]
    surface = draft.description.surface("dining_table")
    assert surface is not None, draft.source()
    stood_in = any(s.link == "dining_table" for s in draft.description.stand_ins)
    return surface.height, stood_in


PACKAGE_URI = "package://dining_meshes/meshes/table.stl"


def test_a_package_beside_the_urdf_is_found(tmp_path: Path) -> None:
    urdf = _kitchen(tmp_path / "env", PACKAGE_URI, tmp_path / "env")
    height, stood_in = _table_surface(urdf)
    assert height == pytest.approx(TABLE[2], abs=1e-4) and not stood_in


def test_package_path_and_ros_package_path_find_the_package(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    workspace = tmp_path / "far" / "away" / "workspace"  # too far to be "beside" the URDF
    uri = "package://far_meshes/meshes/table.stl"  # a name no other test's folder holds
    urdf = _kitchen(tmp_path / "env", uri, workspace / "src", "far_meshes")
    assert _table_surface(urdf)[1]  # not found: a guessed stand-in table
    height, stood_in = _table_surface(urdf, package_paths=[workspace])
    assert height == pytest.approx(TABLE[2], abs=1e-4) and not stood_in
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(workspace))
    height, _ = _table_surface(urdf)
    assert height == pytest.approx(TABLE[2], abs=1e-4)


def test_env_draft_takes_package_path_and_the_scene_loads_the_mesh(tmp_path: Path) -> None:
    urdf = _kitchen(tmp_path / "env", PACKAGE_URI, tmp_path / "elsewhere")
    out = tmp_path / "dining.py"
    assert main(["env", "draft", str(urdf), "--package-path", str(tmp_path / "elsewhere"),
                 "-o", str(out)]) == 0  # fmt: skip
    assert "package_paths=" in out.read_text("utf-8")
    draft = draft_environment(urdf, package_paths=[tmp_path / "elsewhere"])
    desc = draft.description
    loadable = loadable_urdf(desc.urdf, desc.stand_ins, package_paths=desc.package_paths)
    with World() as world:
        table = world.add_urdf("dining", loadable)
        index = table.link_index["dining_table"]
        low, high = pybullet.getAABB(table.body_id, index, physicsClientId=world.physics.client())
        extents = [h - lo for lo, h in zip(low, high, strict=True)]
    assert extents == pytest.approx(list(TABLE), abs=0.02)  # Bullet's margin


def test_a_relative_mesh_path_is_found(tmp_path: Path) -> None:
    urdf = _kitchen(tmp_path / "env", "dining_meshes/meshes/table.stl", tmp_path / "env")
    height, stood_in = _table_surface(urdf)
    assert height == pytest.approx(TABLE[2], abs=1e-4) and not stood_in

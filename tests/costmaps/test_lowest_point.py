"""The robot's lowest point kept on disk: the value worked out, a damaged entry worked out
again, a mesh changed in place a new entry.

A two-link robot hangs a box and an STL mesh below its base frame; the lowest point is
known from the numbers written into its files (an independent path)."""

from __future__ import annotations

import os
import struct
from pathlib import Path

import numpy as np
import pytest

from robocram.costmaps.lowest_point import lowest_point
from robocram.robots import RobotModel
from robocram.robots.link_centre import mesh_box, mesh_points

URDF = """<robot name="hanger">
  <link name="base">
    <collision><origin xyz="0 0 -0.3"/><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <link name="foot">
    <collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
  <joint name="hang" type="fixed">
    <parent link="base"/><child link="foot"/><origin xyz="0.1 0 -0.5"/>
  </joint>
</robot>
"""


def _write_stl(path: Path, lowest_z: float) -> None:
    """A binary STL of one triangle reaching down to ``lowest_z`` in its frame."""
    triangle = struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 0.1, 0, 0, 0, 0.1, lowest_z, 0)
    path.write_bytes(b"\0" * 80 + struct.pack("<I", 1) + triangle)


@pytest.fixture
def robot(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[Path, Path]:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path / "cache"))
    mesh = tmp_path / "foot.stl"
    _write_stl(mesh, -0.25)
    urdf = tmp_path / "hanger.urdf"
    urdf.write_text(URDF.format(mesh=mesh))
    return urdf, mesh


def _entries(tmp_path: Path) -> list[Path]:
    return sorted((tmp_path / "cache" / "lowest-points").glob("*.arrays"))


def test_kept_then_read_back(robot: tuple[Path, Path], tmp_path: Path) -> None:
    urdf, _ = robot
    # the foot's mesh reaches 0.25 m below the foot, 0.5 m below the base: -0.75 m
    assert lowest_point(RobotModel.from_file(urdf)) == pytest.approx(-0.75, abs=1e-6)
    assert len(_entries(tmp_path)) == 1
    assert lowest_point(RobotModel.from_file(urdf)) == pytest.approx(-0.75, abs=1e-6)


def test_a_damaged_entry_is_worked_out_again(robot: tuple[Path, Path], tmp_path: Path) -> None:
    urdf, _ = robot
    lowest_point(RobotModel.from_file(urdf))
    (entry,) = _entries(tmp_path)
    data = bytearray(entry.read_bytes())
    at = len(data) - 8  # the value's bytes: a plausible number, only the CRC says no
    data[at:] = np.array(-9.0).tobytes()
    entry.write_bytes(bytes(data))
    assert lowest_point(RobotModel.from_file(urdf)) == pytest.approx(-0.75, abs=1e-6)
    assert np.frombuffer(entry.read_bytes()[-8:], "<f8")[0] == pytest.approx(-0.75, abs=1e-6)


def test_a_mesh_changed_in_place_is_a_new_entry(robot: tuple[Path, Path], tmp_path: Path) -> None:
    urdf, mesh = robot
    lowest_point(RobotModel.from_file(urdf))
    _write_stl(mesh, -0.45)  # longer foot, same path (a new size or time stamps it)
    stat = mesh.stat()
    os.utime(mesh, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    mesh_points.cache_clear()  # as a new process: this one keeps what it read per file
    mesh_box.cache_clear()
    assert lowest_point(RobotModel.from_file(urdf)) == pytest.approx(-0.95, abs=1e-6)
    assert len(_entries(tmp_path)) == 2

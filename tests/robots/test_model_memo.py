"""Loads of one robot file share one parsed model while it is held; a changed file is
parsed anew, and a model nobody holds is not kept by the memo."""

from __future__ import annotations

import gc
import weakref
from pathlib import Path

import pytest

from robocram.robots.errors import MissingMeshWarning
from robocram.robots.model_memo import ModelMemo
from robocram.robots.robot_model import RobotModel

ARM = """<robot name="arm">
  <link name="base"/><link name="tip"/>
  <joint name="j" type="revolute"><parent link="base"/><child link="tip"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="{upper}" effort="1" velocity="1"/></joint>
</robot>"""


def test_equal_bytes_share_a_model_and_a_changed_file_is_read_again(tmp_path: Path) -> None:
    file = tmp_path / "arm.urdf"
    file.write_text(ARM.format(upper=1.0))
    memo: ModelMemo[RobotModel] = ModelMemo()
    built: list[RobotModel] = []

    def build() -> RobotModel:
        built.append(RobotModel.from_string(file.read_text()))
        return built[-1]

    first = memo.model(file, (), (), (), build)
    assert memo.model(file, (), (), (), build) is first and len(built) == 1
    file.write_text(ARM.format(upper=2.0))
    changed = memo.model(file, (), (), (), build)
    assert changed is not first and changed.joints["j"].upper == 2.0
    assert len(built) == 2


def test_a_shared_model_warns_again_on_every_load(tmp_path: Path) -> None:
    file = tmp_path / "arm.urdf"
    file.write_text(ARM.format(upper=1.0).replace(
        '<link name="tip"/>',
        '<link name="tip"><visual><geometry><mesh filename="gone.stl"/></geometry></visual></link>',
    ))  # fmt: skip
    for _ in range(2):
        with pytest.warns(MissingMeshWarning, match="gone.stl"):
            RobotModel.from_file(file)


def test_the_memo_keeps_no_model_alive(tmp_path: Path) -> None:
    memo: ModelMemo[RobotModel] = ModelMemo()
    file = tmp_path / "arm.urdf"
    file.write_text(ARM.format(upper=1.0))
    built: list[int] = []

    def build() -> RobotModel:
        built.append(1)
        return RobotModel.from_string(file.read_text())

    held = memo.model(file, (), (), (), build)
    assert memo.model(file, (), (), (), build) is held and len(memo) == 1
    dead = weakref.ref(held)
    del held
    gc.collect()
    assert dead() is None and len(memo) == 0  # nothing but its users kept it
    again = memo.model(file, (), (), (), build)
    assert again.joints["j"].upper == 1.0 and len(built) == 2  # parsed anew

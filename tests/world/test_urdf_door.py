"""Every URDF reaches PyBullet through the checked parser (issue 24, item 1).

Before: ``add_urdf`` handed files straight to PyBullet. A loop below the root killed the
process, crossed limits were taken, a 129-link body raised a raw ``pybullet.error`` and
stayed half-made, and Latin-1 or UTF-16 files failed with no reason given.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import pybullet
import pytest

from robocram.world import BodyLoadError, TooManyLinksError, World


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        yield w


def _bodies(world: World) -> int:
    return int(pybullet.getNumBodies(physicsClientId=world.physics.client()))


def _chain(n_joints: int, name: str = "snake") -> str:
    links = "\n".join(f'<link name="l{i}"/>' for i in range(n_joints + 1))
    joints = "\n".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        '<limit lower="-1" upper="1"/></joint>'
        for i in range(n_joints)
    )
    return f'<robot name="{name}">\n{links}\n{joints}\n</robot>\n'


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def _unchanged(world: World) -> bool:
    return [o.name for o in world.objects()] == ["floor"] and _bodies(world) == 1


def test_a_loop_below_the_root_is_refused_and_the_process_lives(
    world: World, tmp_path: Path
) -> None:
    urdf = _write(
        tmp_path / "loop.urdf",
        '<robot name="loop"><link name="base"/><link name="a"/><link name="b"/>'
        '<joint name="ja" type="fixed"><parent link="base"/><child link="a"/></joint>'
        '<joint name="jb" type="fixed"><parent link="a"/><child link="b"/></joint>'
        '<joint name="jc" type="fixed"><parent link="b"/><child link="a"/></joint></robot>',
    )
    with pytest.raises(BodyLoadError, match=r"link 'a' is the child of joints 'ja' and 'jc'"):
        world.add_urdf("loop", urdf)
    assert _unchanged(world)


def test_crossed_limits_are_refused(world: World, tmp_path: Path) -> None:
    urdf = _write(
        tmp_path / "crossed.urdf", _chain(1).replace('lower="-1" upper="1"', 'lower="1" upper="-1"')
    )
    with pytest.raises(BodyLoadError, match=r"joint 'j0' has lower limit 1.0 > upper -1.0"):
        world.add_urdf("crossed", urdf)
    assert _unchanged(world)


def test_a_body_of_129_links_is_refused_before_loading(world: World, tmp_path: Path) -> None:
    urdf = _write(tmp_path / "snake.urdf", _chain(128))
    with pytest.raises(TooManyLinksError, match=r"it has 128 links below its root .* at most 127"):
        world.add_urdf("snake", urdf)
    assert _unchanged(world)


def test_a_body_of_122_moving_joints_is_refused(world: World, tmp_path: Path) -> None:
    urdf = _write(tmp_path / "snake.urdf", _chain(122))
    with pytest.raises(TooManyLinksError, match=r"it has 122 moving joints .* at most 121"):
        world.add_urdf("snake", urdf)
    assert _unchanged(world)


def test_a_body_of_121_moving_joints_sets_its_last_joint(world: World, tmp_path: Path) -> None:
    world.add_urdf("snake", _write(tmp_path / "snake.urdf", _chain(121)))
    world.set_joint_states("snake", {"j120": 0.5})
    states = world.joint_states("snake")
    assert len(states) == 121 and states["j120"] == pytest.approx(0.5, abs=1e-12)


def test_a_body_of_128_links_with_fixed_joints_answers_joint_queries(
    world: World, tmp_path: Path
) -> None:
    text = _chain(127).replace('type="revolute"', 'type="fixed"', 100)
    world.add_urdf("snake", _write(tmp_path / "snake.urdf", text))
    world.set_joint_states("snake", {"j126": 0.5})
    states = world.joint_states("snake")
    assert len(states) == 27 and states["j126"] == pytest.approx(0.5, abs=1e-12)


def test_a_latin1_file_declaring_its_encoding_loads(world: World, tmp_path: Path) -> None:
    text = '<?xml version="1.0" encoding="ISO-8859-1"?>\n' + _chain(1).replace("l1", "bras_\xe9")
    urdf = tmp_path / "latin.urdf"
    urdf.write_bytes(text.encode("latin-1"))
    world.add_urdf("latin", urdf)
    assert world.link_names("latin") == ["l0", "bras_\xe9"]
    assert world.bodies.joint_limits("latin", "j0").upper == pytest.approx(1.0)


def test_a_utf16_file_loads(world: World, tmp_path: Path) -> None:
    text = '<?xml version="1.0" encoding="UTF-16"?>\n' + _chain(2).replace("l2", "pince_\xe9")
    urdf = tmp_path / "wide.urdf"
    urdf.write_bytes(text.encode("utf-16"))
    world.add_urdf("wide", urdf)
    assert world.link_names("wide") == ["l0", "l1", "pince_\xe9"]


def test_a_file_in_another_encoding_than_declared_says_which_byte(
    world: World, tmp_path: Path
) -> None:
    urdf = tmp_path / "liar.urdf"
    urdf.write_bytes(_chain(1).replace("l1", "bras_\xe9").encode("latin-1"))
    with pytest.raises(BodyLoadError, match=r"byte 0xe9 is not utf-8; declare the file's encoding"):
        world.add_urdf("liar", urdf)
    assert _unchanged(world)


def test_a_pybullet_refusal_carries_its_reason(world: World, tmp_path: Path) -> None:
    urdf = _write(
        tmp_path / "meshless.urdf",
        '<robot name="r"><link name="a"><collision><geometry><mesh filename="nope.obj"/>'
        "</geometry></collision></link></robot>",
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the parser's stand-in boxes are not what loads
        with pytest.raises(BodyLoadError, match=r"cannot find 'nope.obj' in any directory"):
            world.add_urdf("meshless", urdf)
    assert _unchanged(world)

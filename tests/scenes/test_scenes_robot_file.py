"""A robot file goes wherever a robot's name goes; scenes park the arms (issue 25, items 1-3).

The robot is the Fetch as `robocram robot draft` wrote it from its public URDF (tests/data/
fetch, meshes left out): at its zero pose the arm hangs in front of its head camera.
"""

from __future__ import annotations

import runpy
import sys
import textwrap
import warnings
from dataclasses import replace
from pathlib import Path

import pytest

from robocram.cli import main
from robocram.designators import a, an
from robocram.execution import perform
from robocram.execution.failures import PerceptionBlockedByRobot
from robocram.projection import simulated_robot
from robocram.robots import DescriptionError, load_description
from robocram.scenes import tabletop_scene

FETCH = Path(__file__).resolve().parents[1] / "data" / "fetch" / "fetch.py"


@pytest.fixture(autouse=True)
def _no_mesh_warnings() -> None:
    warnings.filterwarnings("ignore", message=".*mesh.*")


def _readme_snippet(scene_robot: str, scene: object) -> object:
    """The README's lines: torso up, look at the mug, detect it."""
    world = scene.world  # type: ignore[attr-defined]
    top = world.kb.first(
        "robot_torso_link_joint(R, _, J), joint_upper_limit(R, J, Top)", R=scene_robot
    )
    with simulated_robot(world, scene_robot):
        perform(a.motion(type="moving-torso", joint_angle=top["Top"]))
        perform(a.motion(type="looking", target=a.location(pose=scene.look_target)))  # type: ignore[attr-defined]
        return perform(a.motion(type="detecting", object=an.object(type="mug")))


def test_load_description_takes_a_drafted_file() -> None:
    desc = load_description(str(FETCH))
    assert desc.name == "fetch"
    assert desc.torso_joint == "torso_lift_joint"
    assert set(desc.arms) == {"arm"}


def test_unknown_robot_name_says_a_file_is_accepted() -> None:
    with pytest.raises(DescriptionError, match=r"no built-in robot 'fetch'.*\.py file"):
        load_description("fetch")


def test_the_tabletop_scene_parks_the_arms() -> None:
    scene = tabletop_scene(str(FETCH))
    try:
        desc = scene.world.robot(scene.robot).description
        parking = desc.arms["arm"].parking
        joints = scene.world.joint_states(scene.robot)
        assert {j: joints[j] for j in parking} == pytest.approx(dict(parking), abs=1e-6)
        assert any(abs(v) > 0.1 for v in parking.values())  # not the zero pose
    finally:
        scene.world.close()


def test_readme_snippet_runs_on_the_drafted_fetch() -> None:
    scene = tabletop_scene(str(FETCH))
    try:
        mug = _readme_snippet(scene.robot, scene)
        pose = mug.get("pose")  # type: ignore[attr-defined]
        assert pose.frame_id == "base_link"
        assert pose.position[0] == pytest.approx(scene.look_target.position[0], abs=0.05)
        assert mug.get("name") == "mug-1"  # type: ignore[attr-defined]
    finally:
        scene.world.close()


def test_perception_names_the_robots_own_link_in_the_way() -> None:
    scene = tabletop_scene(str(FETCH))
    try:
        parking = scene.world.robot(scene.robot).description.arms["arm"].parking
        scene.world.set_joint_states(scene.robot, dict.fromkeys(parking, 0.0))  # arm hangs
        with pytest.raises(PerceptionBlockedByRobot) as caught:
            _readme_snippet(scene.robot, scene)
        arm = scene.world.robot(scene.robot).description.arms["arm"]
        assert caught.value.link in arm.links  # the hanging arm's (stand-in boxes: issue 37)
        assert caught.value.target == "mug-1"
        assert "parking-arms" in str(caught.value)
        assert caught.value.arm_parked is False
    finally:
        scene.world.close()


def test_a_parked_arm_in_the_view_is_told_to_park_elsewhere_not_to_park() -> None:
    """Issue 37: "park the arms before looking" was said when they were parked."""
    desc = load_description(str(FETCH))
    arm = desc.arms["arm"]
    hanging = replace(arm, parking=dict.fromkeys(arm.parking, 0.0))  # parked where it hangs
    scene = tabletop_scene(replace(desc, arms={"arm": hanging}))
    try:
        with pytest.raises(PerceptionBlockedByRobot) as caught:
            _readme_snippet(scene.robot, scene)
        text = str(caught.value)
        assert caught.value.arm_parked is True
        assert "arm 'arm' is parked" in text and "parking pose" in text
        assert "park the arms before looking" not in text
    finally:
        scene.world.close()


def test_demo_command_runs_a_robot_file(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "--robot", str(FETCH)]) == 0
    out = capsys.readouterr().out
    assert "pick" in out.lower()


def test_demo_command_names_the_ways_for_an_unknown_robot(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["demo", "--robot", "fetch"]) == 3
    err = capsys.readouterr().err
    assert "no built-in robot 'fetch'" in err and ".py file" in err


def test_example_script_runs_a_robot_file(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    example = Path(__file__).resolve().parents[2] / "examples" / "pick_mug.py"
    monkeypatch.setattr(sys, "argv", [str(example), str(FETCH)])
    runpy.run_path(str(example), run_name="__main__")
    assert "fetch: arm arm holds mug-1" in capsys.readouterr().out


def test_batch_spec_takes_a_robot_file_relative_to_the_spec(tmp_path: Path) -> None:
    from robocram.batch import load_spec

    (tmp_path / "robots").mkdir()
    (tmp_path / "robots" / "mine.py").write_text(
        f"from robocram.robot_check import description_from\n"
        f"def description():\n    return description_from({str(FETCH)!r})\n"
    )
    spec = tmp_path / "spec.yaml"
    spec.write_text(textwrap.dedent("robot: robots/mine.py\nvariants: 1\n"))
    robot = load_spec(spec).robot
    assert robot == str(tmp_path / "robots" / "mine.py")
    assert load_description(robot).name == "fetch"

"""The README's example runs as written on every robot it names and finds the scene's mug."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
ROBOT_LINE = re.compile(r'^robot = "(\w+)" +# or ((?:"\w+"(?:, )?)+).*$', re.M)
STRETCH = Path(__file__).resolve().parent / "data" / "stretch" / "stretch.py"


def example() -> str:
    code = re.search(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    assert code is not None, "the README lost its example"
    return code.group(1)


def named_robots() -> list[str]:
    line = ROBOT_LINE.search(example())
    assert line is not None, 'the example lost its line robot = "..."  # or "...", "..."'
    return [line.group(1), *re.findall(r'"(\w+)"', line.group(2))]


def test_the_example_names_the_three_built_in_manipulators() -> None:
    assert named_robots() == ["pr2", "hsrb", "boxy"]


@pytest.mark.parametrize("robot", named_robots())
def test_readme_example_runs_on_each_robot_it_names(robot: str) -> None:
    code = ROBOT_LINE.sub(f'robot = "{robot}"', example(), count=1)
    namespace: dict[str, object] = {}
    exec(compile(code, str(README), "exec"), namespace)
    pose = namespace["mug"].get("pose")  # type: ignore[attr-defined]
    assert pose.frame_id == "base_footprint"
    world = namespace["scene"].world  # type: ignore[attr-defined]
    placed = world.pose(robot).inverse() * world.pose("mug-1")
    assert pose.position == pytest.approx(placed.position, abs=1e-3)
    torso = world.robot(robot).description.torso_joint
    limits = world.robot(robot).description.model.joints[torso]
    assert limits.lower is not None and limits.upper is not None
    quarter = limits.lower + (limits.upper - limits.lower) / 4
    assert world.joint_states(robot)[torso] == pytest.approx(quarter, abs=1e-6)
    assert namespace["up"] == pytest.approx(quarter, abs=1e-12)
    world.close()


def test_readme_example_runs_on_a_description_file_without_a_torso() -> None:
    """Issue 37: ``R=robot`` was the file's path, and ``torso`` None on a robot without a
    lifting torso (Stretch's lift carries its arm only)."""
    code = ROBOT_LINE.sub(f"robot = {str(STRETCH)!r}", example(), count=1)
    namespace: dict[str, object] = {}
    exec(compile(code, str(README), "exec"), namespace)
    scene = namespace["scene"]
    world, name = scene.world, scene.robot  # type: ignore[attr-defined]
    assert namespace["torso"] is None and "up" not in namespace
    pose = namespace["mug"].get("pose")  # type: ignore[attr-defined]
    placed = world.pose(name).inverse() * world.pose("mug-1")
    assert pose.position == pytest.approx(placed.position, abs=1e-3)
    world.close()

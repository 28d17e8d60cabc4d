"""Batch specs: variants drawn from seeded ranges or listed, bad keys named with the fix."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from robocram.batch import BadSpec, Variant
from robocram.batch.batch_spec import SPEC_KEYS, load_spec
from robocram.plans import pick_up
from robocram.scenes import tabletop_scene
from robocram.tf import quaternion

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "batch_tabletop.yaml"


def test_the_example_draws_six_variants_inside_its_ranges() -> None:
    spec = load_spec(EXAMPLE)
    assert (spec.scene, spec.plan, spec.robot) == (tabletop_scene, pick_up, "pr2")
    assert [v.name for v in spec.variants] == [f"v{i:03d}" for i in range(6)]
    assert [v.seed for v in spec.variants] == list(range(7, 13))
    for v in spec.variants:
        ((name, (dx, dy, dz, dyaw)),) = v.object_shifts
        assert name == "mug-1" and v.look_at == "mug-1"
        assert -0.04 <= dx <= 0.04 and -0.12 <= dy <= 0.12 and dz == 0.0
        assert -3.1416 <= dyaw <= 3.1416
        ((bottle, pose),) = v.object_poses
        assert bottle == "bottle-1" and pose[0] == 0.95 and pose[2] == 0.74
        assert 0.25 <= pose[1] <= 0.4 and pose[3:] == (0.0, 0.0, 0.0, 1.0)
    assert len({v.object_shifts for v in spec.variants}) == 6  # six different draws
    assert load_spec(EXAMPLE) == spec  # the seed fixes the draws


def _write(tmp_path: Path, data: object, suffix: str = ".json") -> Path:
    path = tmp_path / f"spec{suffix}"
    path.write_text(json.dumps(data), encoding="utf-8")
    return path


def test_another_seed_draws_other_placements(tmp_path: Path) -> None:
    place = {"mug-1": {"frame": "map", "x": [0.5, 0.7], "y": 0.1, "z": 0.62, "yaw": [0, 1]}}
    one = load_spec(_write(tmp_path, {"variants": 3, "seed": 1, "place": place}))
    two = load_spec(_write(tmp_path, {"variants": 3, "seed": 2, "place": place}))
    assert one.variants != two.variants
    for v in one.variants:
        ((_, pose),) = v.object_poses
        assert 0.5 <= pose[0] <= 0.7 and pose[1:3] == (0.1, 0.62)
        assert 0.0 <= quaternion.to_euler(pose[3:])[2] <= 1.0


def test_listed_variants_are_read_as_given(tmp_path: Path) -> None:
    listed = [
        {"name": "near", "object_shifts": {"mug-1": [0.0, 0.05, 0.0]}, "look_at": "mug-1"},
        {"name": "turned", "object_poses": {"mug-1": [0.6, 0.0, 0.62, math.pi]}, "seed": 3},
    ]
    spec = load_spec(_write(tmp_path, {"robot": "hsrb", "variants": listed, "workers": 1}))
    assert spec.variants == (
        Variant("near", object_shifts={"mug-1": (0.0, 0.05, 0.0)}, look_at="mug-1"),
        Variant("turned", object_poses={"mug-1": (0.6, 0.0, 0.62, math.pi)}, seed=3),
    )
    assert (spec.robot, spec.workers, spec.backend) == ("hsrb", 1, None)


def test_a_plan_next_to_the_spec_is_imported(tmp_path: Path) -> None:
    (tmp_path / "my_plans.py").write_text("def wave(target):\n    return target\n", "utf-8")
    spec = load_spec(_write(tmp_path, {"plan": "my_plans:wave", "variants": 1}))
    assert spec.plan.__name__ == "wave" and spec.plan.__module__ == "my_plans"


@pytest.mark.parametrize(
    ("data", "culprit"),
    [
        ({"variants": 2, "robots": "pr2"}, "robots='pr2': not a spec key; use scene, robot"),
        ({"variants": 0}, "variants=0: give a count"),
        ({"variants": "many"}, "variants='many'"),
        ({"variants": 2, "seed": -3}, "seed=-3"),
        ({"variants": 2, "plan": "fly"}, "plan=.fly.: use breakfast, pick_up, transport or module"),
        ({"variants": 2, "scene": "nowhere:scene"}, "scene='nowhere:scene': cannot import"),
        ({"variants": 2, "workers": 0}, "workers=0: give a positive integer"),
        ({"variants": 2, "place": {"mug-1": {"x": [1, 0]}}}, r"place\['mug-1'\].x=\[1, 0\]"),
        ({"variants": 2, "place": {"mug-1": {"roll": 1}}}, r"place\['mug-1'\].roll=1: use frame"),
        ({"variants": 2, "place": {"mug-1": {"frame": "base"}}}, "frame='base': use scene or map"),
        ({"variants": 2, "place": {"mug-1": {"frame": "map", "x": 1}}}, "needs x, y and z"),
        ({"variants": 2, "place": {"mug-1": 0.1}}, r"place\['mug-1'\]=0.1"),
        ({"variants": [{"name": "a", "sede": 1}], "seed": 1}, r"variants\[0\].*sede"),
        ({"variants": [{"name": "a"}], "place": {}}, "place=.*give `variants: N`"),
        ({"variants": 1, "jitter": -1}, "jitter=-1"),
        ([1, 2], r"\(top level\)"),
    ],
)
def test_bad_specs_name_the_key(tmp_path: Path, data: object, culprit: str) -> None:
    with pytest.raises(BadSpec, match=culprit):
        load_spec(_write(tmp_path, data))


def test_bad_files_are_named(tmp_path: Path) -> None:
    with pytest.raises(BadSpec, match="give a .yaml, .yml or .json"):
        load_spec(tmp_path / "spec.toml")
    with pytest.raises(BadSpec, match="cannot read it"):
        load_spec(tmp_path / "missing.yaml")
    broken = tmp_path / "broken.yaml"
    broken.write_text("variants: [1,\n", encoding="utf-8")
    with pytest.raises(BadSpec, match="not valid yaml"):
        load_spec(broken)
    assert "backend" in SPEC_KEYS


@pytest.mark.parametrize(
    ("robot", "culprit"),
    [
        ("/nowhere/robot.py", r"robot='/nowhere/robot.py': no file /nowhere/robot.py"),
        ("{folder}", "no built-in robot"),
        ("{folder}/robot.urdf", "a URDF is no robot description; draft one"),
        ("{folder}/empty.py", "empty.py"),
        ("empty.py", "empty.py"),
    ],
)
def test_the_robot_is_checked_up_front(tmp_path: Path, robot: str, culprit: str) -> None:
    (tmp_path / "empty.py").write_text("", "utf-8")
    (tmp_path / "robot.urdf").write_text("<robot name='r'/>", "utf-8")
    data = {"variants": 1, "robot": robot.format(folder=tmp_path)}
    with pytest.raises(BadSpec, match=culprit) as caught:
        load_spec(_write(tmp_path, data))
    assert caught.value.key == "robot"

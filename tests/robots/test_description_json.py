"""A description written as JSON reads back to the same values (issue 41: traces keep it)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from robocram.robots import load_description
from robocram.robots.description_json import (
    DescriptionRecordError,
    description_from_json,
    description_to_json,
)

ROOT = Path(__file__).resolve().parents[2]
SPECS = ("pr2", "hsrb", "boxy", str(ROOT / "tests/data/stretch/stretch.py"))


@pytest.mark.parametrize("spec", SPECS)
def test_a_loaded_description_reads_back_field_for_field(spec: str) -> None:
    desc = load_description(spec)
    text = description_to_json(desc)
    back = description_from_json(text, desc.model, desc.source)
    assert description_to_json(back) == text
    assert back.arms.keys() == desc.arms.keys()
    for key, arm in desc.arms.items():  # nested values, by an independent path: the fields
        assert back.arms[key].parking == arm.parking
        assert back.arms[key].joints == arm.joints
        assert back.arms[key].gripper == arm.gripper
    assert back.cameras == desc.cameras and back.extra_frames == desc.extra_frames
    assert back.coupled_joints == desc.coupled_joints and back.drive == desc.drive
    assert load_description(back).model is desc.model  # given the model, nothing is re-read


def test_a_value_of_the_wrong_type_names_the_field() -> None:
    values = json.loads(description_to_json(load_description("hsrb")))
    values["cameras"][0]["horizontal_fov"] = "wide"
    with pytest.raises(DescriptionRecordError, match=r"description\.cameras\[0\]\.horizontal_fov"):
        description_from_json(json.dumps(values))


def test_a_field_this_robocram_does_not_know_is_refused_with_the_fix() -> None:
    values = json.loads(description_to_json(load_description("hsrb")))
    values["wings"] = 2
    with pytest.raises(DescriptionRecordError, match="no field 'wings'.*--robot-file"):
        description_from_json(json.dumps(values))

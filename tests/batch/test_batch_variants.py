"""Variants as plain data: the placements they accept, and errors that name the bad key."""

from __future__ import annotations

import math
import pickle

import pytest

from robocram.batch import BadVariant, Variant
from robocram.tf import Pose, quaternion


def test_absolute_poses_take_a_yaw_or_a_full_pose() -> None:
    v = Variant(
        "v",
        object_poses={
            "mug-1": (0.6, -0.1, 0.62, math.pi / 2),
            "bottle-1": Pose((0.7, 0.3, 0.7), quaternion.from_euler(0.0, 0.0, 0.5)),
            "cup": ((0.1, 0.2, 0.3), (0.0, 0.0, 0.0, 2.0)),  # normalised
            "box": (1.0, 2.0, 3.0),  # upright, yaw 0
        },
    )
    poses = dict(v.object_poses)
    assert poses["mug-1"][:3] == (0.6, -0.1, 0.62)
    assert quaternion.to_euler(poses["mug-1"][3:])[2] == pytest.approx(math.pi / 2)
    assert quaternion.to_euler(poses["bottle-1"][3:])[2] == pytest.approx(0.5)
    assert poses["cup"][3:] == (0.0, 0.0, 0.0, 1.0)
    assert poses["box"] == (1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0)
    assert [name for name, _ in v.object_poses] == ["bottle-1", "box", "cup", "mug-1"]
    assert pickle.loads(pickle.dumps(v)) == v and hash(v) == hash(pickle.loads(pickle.dumps(v)))


def test_shifts_take_an_optional_turn() -> None:
    v = Variant("v", object_shifts={"mug-1": (0.0, 0.1, 0.0), "bottle-1": (0.1, 0.0, 0.0, 0.4)})
    assert dict(v.object_shifts) == {
        "mug-1": (0.0, 0.1, 0.0, 0.0),
        "bottle-1": (0.1, 0.0, 0.0, 0.4),
    }


@pytest.mark.parametrize(
    ("data", "culprit"),
    [
        ({"name": "a", "object_pose": {}}, "object_pose=.*not a variant key; use name, robot"),
        ({"robot": "pr2"}, "name=None: every variant needs a name"),
        ({"name": "a", "object_poses": {"mug-1": (1.0, 2.0)}}, r"object_poses\['mug-1'\]"),
        ({"name": "a", "object_poses": {"mug-1": (0, 0, 0, math.inf)}}, r"object_poses\['mug-1'\]"),
        ({"name": "a", "object_shifts": {"mug-1": "left"}}, r"object_shifts\['mug-1'\]"),
        ({"name": "a", "object_shifts": [1, 2]}, "object_shifts=1"),
        ({"name": "a", "robot": 3}, "robot=3: give a name"),
        ({"name": "a", "look_at": ""}, "look_at='': give a name"),
        ({"name": "a", "seed": -1}, "seed=-1"),
        ({"name": "a", "seed": 1.5}, "seed=1.5"),
        ({"name": "a", "jitter": "big"}, "jitter='big'"),
        ({"name": "a", "parameters": {"not a name": 1}}, "parameters='not a name'"),
        ({"name": "a", "tags": [1]}, r"tags=\(1,\)"),
        (
            {"name": "a", "object_shifts": {"m": (0, 0, 0)}, "object_poses": {"m": (0, 0, 0)}},
            "shift an object or pose it, not both",
        ),
    ],
)
def test_bad_variants_name_the_key(data: dict[str, object], culprit: str) -> None:
    with pytest.raises(BadVariant, match=culprit):
        Variant.from_mapping(data)


def test_from_mapping_matches_the_constructor() -> None:
    data = {
        "name": "a",
        "robot": "hsrb",
        "object_shifts": {"mug-1": [0.0, 0.05, 0.0]},
        "parameters": {"object_type": "mug"},
        "look_at": "mug-1",
        "seed": 4,
        "tags": ["near"],
    }
    assert Variant.from_mapping(data) == Variant(
        "a",
        robot="hsrb",
        object_shifts={"mug-1": (0.0, 0.05, 0.0)},
        parameters={"object_type": "mug"},
        look_at="mug-1",
        seed=4,
        tags=("near",),
    )

"""A user's own key: one Prolog rule and one Python function (as docs/locations.md shows)."""

from __future__ import annotations

import itertools
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from robocram.costmaps import CostLayer, CostmapInputError, CostmapLocations, LocationQuery
from robocram.designators import a
from robocram.tf import Pose
from robocram.world import World

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def away_from_cost(query: LocationQuery, value: Any, alive: np.ndarray) -> CostLayer:
    """Prefer cells far from the object ``value`` (up to 2 m)."""
    cx, cy, _ = query.point(value, "away_from")
    x, y = query.centres()
    return CostLayer(np.clip(np.hypot(x - cx, y - cy) / 2.0, 0.0, 1.0))


def test_a_new_key_needs_one_rule_and_one_function() -> None:
    with World() as world:
        world.bodies.add_floor()
        world.add_robot("pr2")
        world.add_box("table", (0.6, 1.0, 0.7), Pose((1.5, 0.0, 0.35)))
        world.add_box("sink", (0.5, 0.5, 0.9), Pose((1.5, 1.5, 0.45)))
        world.kb.consult("location_cost(away_from, away_from).", group="my_keys")
        locations = CostmapLocations(world, sampling="best")
        locations.add_cost_function("away_from", away_from_cost)
        designator = a.location(near="table", away_from="sink")
        poses = list(itertools.islice(locations.poses(designator), 5))
        sink = world.pose("sink").position
        for pose in poses:
            x, y, _ = pose.position
            assert (
                math.hypot(x - sink[0], y - sink[1]) > 1.9
            )  # as far from the sink as "near" allows
            assert y < 0  # the side of the table away from the sink


def test_the_example_draws_both_pictures(tmp_path: Path) -> None:
    import importlib.util

    spec = importlib.util.spec_from_file_location(
        "costmap_pictures", EXAMPLES / "costmap_pictures.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for path in module.main(str(tmp_path)):
        image = np.asarray(Image.open(path).convert("RGB"), dtype=int)
        heat = image[:, :, 0] - image[:, :, 1] > 40  # tinted red by the weights
        assert image.shape[0] == image.shape[1] >= 200
        assert 0.01 < heat.mean() < 0.9, (path, heat.mean())  # weights drawn, not everywhere


def test_a_rule_without_its_python_function_is_named() -> None:
    with World() as world:
        world.bodies.add_floor()
        world.add_box("table", (0.6, 1.0, 0.7), Pose((1.5, 0.0, 0.35)))
        world.kb.consult("location_cost(under, under_cost).", group="half_done")
        with pytest.raises(CostmapInputError, match="add_cost_function") as caught:
            next(CostmapLocations(world).poses(a.location(under="table")))
        assert caught.value.culprit == "under_cost"

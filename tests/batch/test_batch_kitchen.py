"""Batch transports in the kitchen: each result says the arm, grasp and stands the plan chose."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.batch import VariantStatus, load_spec, project_variants

SPEC = Path(__file__).resolve().parents[2] / "examples" / "batch_kitchen.yaml"


def test_the_kitchen_spec_transports_and_reports_what_was_chosen() -> None:
    spec = load_spec(SPEC)
    variants = spec.variants[:2]
    results = project_variants(
        variants, plan=spec.plan, robot=spec.robot, scene=spec.scene, workers=1
    ).collect()
    assert [r.name for r in results] == [v.name for v in variants]
    done = [r for r in results if r.status is VariantStatus.SUCCEEDED]
    assert done, [r.message for r in results]
    for result in done:
        assert result.arm in ("left", "right")
        assert result.grasp_name is not None and result.grasp_frame == "map"
        assert result.grasp is not None and result.grasp[2] > 0.8  # at the counter's height
        named = dict(result.locations)
        assert {"fetch stand", "deliver stand", "placed at"} <= set(named)
        x, y, z = named["placed at"][:3]
        assert -0.75 < x < 0.75 and -1.9 < y < -0.9  # on the table (1.4 x 0.9 m at (0, -1.4))
        assert z == pytest.approx(0.75, abs=0.05)  # the table's top
        stand = named["deliver stand"]
        assert stand[2] == pytest.approx(0.0, abs=1e-6)  # a base pose on the floor
        assert ((stand[0] - x) ** 2 + (stand[1] - y) ** 2) ** 0.5 < 1.2  # within an arm's reach

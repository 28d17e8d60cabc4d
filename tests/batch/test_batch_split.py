"""A variant's result says where its time went in the worker."""

from __future__ import annotations

import pytest

from robocram.batch import Variant
from robocram.batch.worker import VariantRunner, WorkerConfig
from robocram.plans import pick_up
from robocram.scenes import tabletop_scene


def test_the_split_names_each_phase_and_adds_up_to_the_duration() -> None:
    runner = VariantRunner(WorkerConfig(pick_up, tabletop_scene, "pr2"))
    first = runner.run(0, Variant("first", look_at="mug-1", seed=1))
    second = runner.run(1, Variant("second", look_at="mug-1", seed=2))
    assert first.succeeded and second.succeeded
    phases = [name for name, _ in second.split]
    assert phases == ["scene", "restore", "place", "trace", "robot", "plan"]
    spent = dict(second.split)
    assert sum(spent.values()) == pytest.approx(second.duration, rel=0.05)
    assert spent["plan"] == max(spent.values())  # the pick-up, not the bookkeeping
    assert dict(first.split)["scene"] > dict(second.split)["scene"]  # built once
    assert second.outcome().split == ()  # the split depends on the machine

"""Shared batch fixtures: the test plans importable by name (here and in the workers), and
the 20 reference variants run once on one worker, which every backend must reproduce."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path
from types import ModuleType

import pytest

from robocram.batch import Variant, VariantResult, project_variants

HERE = str(Path(__file__).resolve().parent)


@pytest.fixture
def batch_plans(monkeypatch: pytest.MonkeyPatch) -> ModuleType:
    """The test plans module; workers find it through the parent's ``sys.path``."""
    monkeypatch.syspath_prepend(HERE)
    sys.modules.pop("batch_plans", None)
    return importlib.import_module("batch_plans")


def twenty_variants() -> list[Variant]:
    """18 mug placements (shifted, turned, put at absolute poses, some jittered) and two
    that must fail."""
    shifted = [
        Variant(
            f"mug{i}",
            object_shifts={"mug-1": (0.03 * (i % 3) - 0.03, 0.05 * (i // 3) - 0.15, 0.0, 0.3 * i)},
            jitter=0.01 if i % 2 else 0.0,
            look_at="mug-1",
            seed=i,
        )
        for i in range(14)
    ]
    posed = [
        Variant(f"posed{i}", object_poses={"mug-1": (0.6, y, 0.6157, 0.4 * i)}, look_at="mug-1")
        for i, y in enumerate((-0.25, -0.1, 0.0, 0.12))
    ]
    return [
        *shifted,
        *posed,
        Variant("toaster", parameters={"object_type": "toaster"}),
        Variant("typo", parameters={"objec": "mug"}),
    ]


@pytest.fixture(scope="session")
def reference_variants() -> list[Variant]:
    """:func:`twenty_variants`."""
    return twenty_variants()


@pytest.fixture(scope="session")
def reference_results(reference_variants: list[Variant]) -> list[VariantResult]:
    """The reference variants run on one spawned worker."""
    return project_variants(reference_variants, robot="pr2", workers=1).collect()

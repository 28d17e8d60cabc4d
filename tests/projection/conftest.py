"""Shared fixtures: the example plan, loaded from examples/pick_mug.py (one copy, no fork)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "pick_mug.py"


def load_pick_mug() -> ModuleType:
    """Import examples/pick_mug.py as module ``pick_mug_example``."""
    name = "pick_mug_example"
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, EXAMPLE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def pick_mug_example() -> ModuleType:
    """The example module with ``pick_mug`` and ``make_scene``."""
    return load_pick_mug()

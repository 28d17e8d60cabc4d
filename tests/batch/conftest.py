"""Make ``batch_plans`` importable by name here and in the spawned workers."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path
from types import ModuleType

import pytest

HERE = str(Path(__file__).resolve().parent)


@pytest.fixture
def batch_plans(monkeypatch: pytest.MonkeyPatch) -> ModuleType:
    """The test plans module; workers find it through the parent's ``sys.path``."""
    monkeypatch.syspath_prepend(HERE)
    sys.modules.pop("batch_plans", None)
    return importlib.import_module("batch_plans")

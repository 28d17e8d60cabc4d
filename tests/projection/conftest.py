"""Fixtures of the projection tests: the independent trajectory judge."""

from __future__ import annotations

import importlib.util
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest


def _judge_class() -> Any:
    """``trajectory_judge.Judge`` beside this file (tests are not a package: loaded by path)."""
    path = Path(__file__).with_name("trajectory_judge.py")
    spec = importlib.util.spec_from_file_location("projection_trajectory_judge", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.Judge


@pytest.fixture(scope="session")
def make_judge() -> Callable[..., Any]:
    """``make_judge(world, robot)``: a trajectory listener that judges each trajectory."""
    return _judge_class()

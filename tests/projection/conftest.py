"""Fixtures of the projection tests: the independent trajectory judge."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from robocram.world import World
from tests.projection.trajectory_judge import Judge


@pytest.fixture(scope="session")
def make_judge() -> Callable[[World, str], Judge]:
    """``make_judge(world, robot)``: a trajectory listener that judges each trajectory."""
    return Judge

"""A real roscore on a free port for the ROS tests, started and stopped (by PID) here."""

from __future__ import annotations

import xmlrpc.client
from collections.abc import Callable, Iterator

import pytest

from robocram.ros import Roscore


@pytest.fixture(scope="module")
def roscore() -> Iterator[Roscore]:
    """One ROS master per test module."""
    with Roscore() as core:
        yield core


@pytest.fixture
def master_nodes(roscore: Roscore) -> Callable[[], set[str]]:
    """Every node that publishes, subscribes or serves on the master, asked when called."""

    def nodes() -> set[str]:
        code, _, state = xmlrpc.client.ServerProxy(roscore.uri).getSystemState("/robocram_test")
        assert code == 1
        return {node for kind in state for _, nodes in kind for node in nodes}

    return nodes

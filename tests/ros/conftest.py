"""A real roscore on a free port for the ROS tests, started and stopped (by PID) here, the
projection driver a module's tests share (``driver_pool.py``), reset between them (the
projected kitchen transports the ROS runs are compared with: ``tests/kitchen_transports.py``)."""

from __future__ import annotations

import xmlrpc.client
from collections.abc import Callable, Iterator

import pytest

from robocram.ros import Roscore
from tests.ros.driver_pool import DriverPool


@pytest.fixture(scope="module")
def roscore() -> Iterator[Roscore]:
    """One ROS master per test module."""
    with Roscore() as core:
        yield core


@pytest.fixture(scope="module")
def drivers(roscore: Roscore) -> Iterator[DriverPool]:
    """The module's ROS 1 driver on its roscore, reset for each test that asks for one."""
    pool = DriverPool(roscore.uri)
    try:
        yield pool
    finally:
        pool.close()


@pytest.fixture(scope="module")
def drivers2() -> Iterator[DriverPool]:
    """The module's ROS 2 driver, reset for each test that asks for one; each driver the
    pool starts has a domain of its own, set while a test uses it."""
    pool = DriverPool(ros=2)
    try:
        yield pool
    finally:
        pool.close()


@pytest.fixture
def master_nodes(roscore: Roscore) -> Callable[[], set[str]]:
    """Every node that publishes, subscribes or serves on the master, asked when called."""

    def nodes() -> set[str]:
        code, _, state = xmlrpc.client.ServerProxy(roscore.uri).getSystemState("/robocram_test")
        assert code == 1
        return {node for kind in state for _, nodes in kind for node in nodes}

    return nodes

"""The suite runs on every core (pytest-xdist, ``make unit``); what shares a resource runs
on one worker.

``--dist loadgroup`` sends the tests of one ``xdist_group`` to the same worker, in order:
the batch tests start worker pools and local Ray clusters that would fight over the cores,
the viewer tests start servers and a headless Chromium. The tests of a module that share a
module- or class-scoped fixture run on one worker too, so its set-up (a breakfast for two, a
traced door) runs once, not once per worker. The ROS tests are not one group (together
they took more than half the suite's time on one worker): a module's ``roscore`` is on a
free port, and each ROS 2 test holds a domain no other process holds (``free_domain``).
Modules that share a session-scoped fixture name their ``xdist_group`` themselves
(``pytestmark``); it is kept. Everything else is spread by test.

Each worker takes the next unit (a group or a test) when it runs dry, so the units are
queued longest first (``suite_durations.json``, made by ``tools/suite_durations.py``; with
``--no-loadscope-reorder``, xdist keeps that order): a long group started last would leave
the other worker idle at the end.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Protocol, TypeVar

import pytest

if TYPE_CHECKING:  # imported when first asked for: a plain test run loads no robocram here
    from robocram.robots import RobotDescription
    from tests.kitchen_transports import KitchenTransport, Transports

TESTS = Path(__file__).resolve().parent
GROUPS = {"batch": "batch", "viewer": "viewer"}  # folder -> group
DURATIONS = TESTS / "suite_durations.json"  # node id -> seconds (set-up, call, tear-down)
UNMEASURED = 0.02  # [s] the estimate for a test not in DURATIONS (their mean)


SHARED_SCOPES = ("module", "class")  # fixtures set up once for several tests of a module


def _shares_a_fixture(item: pytest.Item) -> bool:
    """Whether ``item`` uses a fixture kept for more than one test of its module."""
    info = getattr(item, "_fixtureinfo", None)
    if info is None:
        return False
    return any(
        definitions[-1].scope in SHARED_SCOPES for definitions in info.name2fixturedefs.values()
    )


@pytest.hookimpl(wrapper=True)
def pytest_collection_modifyitems(items: list[pytest.Item]) -> Iterator[None]:
    """Put each test of a grouped folder in its folder's ``xdist_group``, and each test
    sharing a module's fixture in its module's: before every other plugin's hook (a
    wrapper's first half runs first), since xdist's names each test by its group there
    (a plain or ``tryfirst`` hook in a conftest ran after it: no test was grouped)."""
    _group(items)
    yield
    grouped = [i for i in items if i.get_closest_marker("xdist_group") is not None]
    loadgroup = bool(items) and getattr(items[0].config.option, "loadgroup", False)
    if loadgroup and grouped and "@" not in grouped[0].nodeid:  # else spread, silently
        raise pytest.UsageError(
            f"xdist did not group {grouped[0].nodeid}: this pytest does not take the "
            "group xdist gives a test (pytest-xdist #1386); install the pytest "
            "pyproject.toml names (make setup)"
        )
    if loadgroup:
        known = json.loads(DURATIONS.read_text()) if DURATIONS.exists() else {}
        items[:] = longest_first(items, known)


def _group(items: list[pytest.Item]) -> None:
    for item in items:
        if item.get_closest_marker("xdist_group") is not None:
            continue  # a group its module names: files sharing a session's fixture
        try:
            relative = Path(str(item.path)).resolve().relative_to(TESTS)
        except ValueError:
            continue  # a doctest of src/
        group = GROUPS.get(relative.parts[0])
        if group is None and _shares_a_fixture(item):
            group = relative.as_posix()
        if group is not None:
            item.add_marker(pytest.mark.xdist_group(group))


class Node(Protocol):
    """What ordering needs of a test: its id."""

    @property
    def nodeid(self) -> str: ...


N = TypeVar("N", bound=Node)


def longest_first(items: Sequence[N], known: Mapping[str, float]) -> list[N]:
    """``items`` with the units xdist deals out (a group, else a test) ordered by their
    estimated time (``known`` seconds per node id, else ``UNMEASURED``), longest first;
    a unit's tests keep their order."""
    unit_of: dict[int, str] = {}
    cost: dict[str, float] = {}
    first: dict[str, int] = {}
    for index, item in enumerate(items):
        plain, unit = _split_group(item.nodeid)
        unit_of[id(item)] = unit
        cost[unit] = cost.get(unit, 0.0) + known.get(plain, UNMEASURED)
        first.setdefault(unit, index)
    return sorted(items, key=lambda i: (-cost[unit_of[id(i)]], first[unit_of[id(i)]]))


def _split_group(nodeid: str) -> tuple[str, str]:
    """The node id without the ``@group`` xdist appends, and the unit xdist deals out: the
    group, else the test (an ``@`` inside a parameter's brackets is not a group's)."""
    if nodeid.rfind("@") > nodeid.rfind("]"):
        plain, _, group = nodeid.rpartition("@")
        return plain, group
    return nodeid, nodeid


@pytest.fixture(scope="session")
def kitchen_transports(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Transports]:
    """``(robot, kind)`` -> its kitchen transport, run once for the session and kept open
    till its end (the modules using it carry ``kitchen_transports.SHARED``: one worker
    runs them)."""
    from tests.kitchen_transports import kitchen_transport, transport_key

    folder = tmp_path_factory.mktemp("kitchen_transports")
    done: dict[tuple[str, str], KitchenTransport] = {}

    def of(robot: str | RobotDescription, kind: str) -> KitchenTransport:
        key = transport_key(robot, kind)
        if key not in done:
            done[key] = kitchen_transport(folder, robot, kind)
        return done[key]

    yield of
    for run in done.values():
        run.world.close()

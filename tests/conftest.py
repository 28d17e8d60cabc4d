"""The suite runs on every core (pytest-xdist, ``make unit``); what shares a resource runs
on one worker.

``--dist loadgroup`` sends the tests of one ``xdist_group`` to the same worker, in order:
the ROS tests share a ``roscore`` and ROS 2 domain ids, the batch tests start worker pools
and local Ray clusters that would fight over the cores, the viewer tests start servers and
a headless Chromium. The tests of a module that share a module- or class-scoped fixture
run on one worker too, so its set-up (a breakfast for two, a traced door) runs once, not once
per worker. Everything else is spread by test.
"""

from __future__ import annotations

from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
GROUPS = {"ros": "ros", "batch": "batch", "viewer": "viewer"}  # folder -> group


SHARED_SCOPES = ("module", "class")  # fixtures set up once for several tests of a module


def _shares_a_fixture(item: pytest.Item) -> bool:
    """Whether ``item`` uses a fixture kept for more than one test of its module."""
    info = getattr(item, "_fixtureinfo", None)
    if info is None:
        return False
    return any(
        definitions[-1].scope in SHARED_SCOPES for definitions in info.name2fixturedefs.values()
    )


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Put each test of a grouped folder in its folder's ``xdist_group``, and each test
    sharing a module's fixture in its module's."""
    for item in items:
        try:
            relative = Path(str(item.path)).resolve().relative_to(TESTS)
        except ValueError:
            continue  # a doctest of src/
        group = GROUPS.get(relative.parts[0])
        if group is None and _shares_a_fixture(item):
            group = relative.as_posix()
        if group is not None:
            item.add_marker(pytest.mark.xdist_group(group))

"""The suite runs on every core (pytest-xdist, ``make unit``); what shares a resource runs
on one worker.

``--dist loadgroup`` sends the tests of one ``xdist_group`` to the same worker, in order:
the ROS tests share a ``roscore`` and ROS 2 domain ids, the batch tests start worker pools
and local Ray clusters that would fight over the cores, the viewer tests start servers and
a headless Chromium. Everything else is spread by test.
"""

from __future__ import annotations

from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
GROUPS = {"ros": "ros", "batch": "batch", "viewer": "viewer"}  # folder -> group


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Put each test of a grouped folder in its folder's ``xdist_group``."""
    for item in items:
        try:
            folder = Path(str(item.path)).resolve().relative_to(TESTS).parts[0]
        except ValueError:
            continue  # a doctest of src/
        group = GROUPS.get(folder)
        if group is not None:
            item.add_marker(pytest.mark.xdist_group(group))

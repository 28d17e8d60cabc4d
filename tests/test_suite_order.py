"""xdist is handed the longest groups and tests first, a group's tests together and in
their order, so no long one is left to the end while the other worker idles."""

from __future__ import annotations

from dataclasses import dataclass

from tests.conftest import UNMEASURED, longest_first


@dataclass(frozen=True)
class Item:
    nodeid: str


def test_units_go_longest_first_and_a_group_stays_together_in_order() -> None:
    items = [
        Item("a.py::quick"),
        Item("ros.py::one@ros"),
        Item("b.py::slow"),
        Item("ros.py::two@ros"),
        Item("b.py::odd[x@y]"),  # an @ in a parameter is no group
        Item("c.py::unknown"),
    ]
    known = {"a.py::quick": 0.01, "ros.py::one": 3.0, "ros.py::two": 4.0, "b.py::slow": 6.5}
    order = [item.nodeid for item in longest_first(items, known)]
    # ros: 7.0 s in all, b.py::slow 6.5 s; the unknown ones count UNMEASURED, kept in order
    assert UNMEASURED > 0.01
    assert order == [
        "ros.py::one@ros",
        "ros.py::two@ros",
        "b.py::slow",
        "b.py::odd[x@y]",
        "c.py::unknown",
        "a.py::quick",
    ]

"""The batch summary says why variants failed: type and cause on one short line, grouped.

Issue 27, item 3: each failed variant's line was cut in the middle of the object designator
(``could not fetch mug-1 in 0 tries: LocationNotFound (object_designator=<ObjectDesi``), so
the reason never showed, and 41 identical failures took 41 lines.
"""

from __future__ import annotations

from robocram.batch import BatchSummary, VariantResult, VariantStatus
from robocram.batch.batch_summary import LINE_WIDTH
from robocram.execution.failures import NavigationPoseUnreachable
from robocram.plans.errors import FetchExhausted

DESIGNATOR = "<ObjectDesignator (an object (type mug) (name mug-1) (pose " + "0.1234, " * 40 + ")>"
NO_STAND = (
    "no stand found for mug-1: LocationNotFound: (a location (reachable-for pr2) (object "
    "mug-1)): no location found after 30 rejections in a row (reachable rejected 30"
)


def _failed(index: int, failure: Exception) -> VariantResult:
    return VariantResult(
        index, f"kitchen-{index}", VariantStatus.FAILED, type(failure).__name__, str(failure)
    )


def test_identical_causes_are_one_line_with_a_count_and_no_designator() -> None:
    fetch = FetchExhausted(NO_STAND, object_designator=DESIGNATOR, attempts=0)
    blocked = NavigationPoseUnreachable("pr2 at (1.0, 2.0, 0.5) would collide", target=DESIGNATOR)
    results = [
        *(_failed(i, fetch) for i in (3, 17, 22)),
        _failed(5, blocked),
        VariantResult(6, "kitchen-6", VariantStatus.SUCCEEDED),
        VariantResult(7, "kitchen-7", VariantStatus.LOST, "WorkerDied", "worker 99 died"),
    ]
    summary = BatchSummary.of(results)
    assert [(c.line.split(":")[0], c.variants) for c in summary.causes] == [
        ("FetchExhausted", ("kitchen-3", "kitchen-17", "kitchen-22")),
        ("NavigationPoseUnreachable", ("kitchen-5",)),
        ("WorkerDied", ("kitchen-7",)),
    ]
    lines = list(summary.cause_lines())
    assert lines[1].split()[:3] == ["3", "FetchExhausted:", "no"]
    assert "no stand found for mug-1: LocationNotFound" in lines[1]
    assert lines[2].split() == ["kitchen-3", "kitchen-17", "kitchen-22"]
    assert lines[3].split() == [
        "1",
        "NavigationPoseUnreachable:",
        "pr2",
        "at",
        "(…)",
        "would",
        "collide",
    ]
    assert all(len(line) <= LINE_WIDTH for line in lines)
    assert not any("ObjectDesignator" in line or "raise stand_retries" in line for line in lines)


def test_many_variants_of_one_cause_stay_within_the_width() -> None:
    failure = FetchExhausted(NO_STAND, object_designator=DESIGNATOR)
    summary = BatchSummary.of([_failed(i, failure) for i in range(41)])
    lines = list(summary.cause_lines())
    assert len(lines) == 3 and lines[1].split()[0] == "41"
    assert len(lines[2]) <= LINE_WIDTH and lines[2].endswith(" …")
    assert lines[2].split()[0] == "kitchen-0"

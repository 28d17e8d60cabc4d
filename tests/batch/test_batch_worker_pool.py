"""The variants a pool hands out: one lost with its node is handed out again first, once;
the summary counts each variant once, with its final outcome, and how many ran again."""

from __future__ import annotations

from robocram.batch import BatchSummary, Variant, VariantResult, VariantStatus
from robocram.batch.worker_pool import Pending


def test_a_variant_is_handed_out_again_first_and_only_once() -> None:
    variants = [Variant("a"), Variant("b"), Variant("c")]
    pending = Pending(variants)
    assert pending.popleft() == (0, variants[0])
    assert pending.retry(0, variants[0]) is True
    assert len(pending) == 3  # b, c and a again
    assert pending.popleft() == (0, variants[0])
    assert pending.retry(0, variants[0]) is False  # lost twice: its result is "lost"
    assert [pending.popleft() for _ in range(len(pending))] == [(1, variants[1]), (2, variants[2])]
    assert not pending and pending.rerun == {0}


def test_the_summary_counts_a_re_run_variant_once_with_its_final_outcome() -> None:
    ok, lost = VariantStatus.SUCCEEDED, VariantStatus.LOST
    results = [
        VariantResult(0, "a", ok, duration=1.0, rerun=True),
        VariantResult(1, "b", lost, "WorkerDied", "its node was lost", rerun=True),
        VariantResult(2, "c", ok, duration=2.0),
        VariantResult(3, "d", lost, "NoWorkerLeft", "not run: every worker was lost"),
    ]
    summary = BatchSummary.of(results)
    assert (summary.variants, summary.succeeded, summary.lost, summary.rerun) == (4, 2, 2, 2)
    assert f"{'re-run after a lost node':<26}{2:>8}" in list(summary.lines())
    assert [c.variants for c in summary.causes] == [("b",), ("d",)]

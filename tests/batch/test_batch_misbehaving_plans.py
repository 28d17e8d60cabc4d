"""A plan that exits, interrupts itself or raises an unprintable error fails its variant;
the worker survives and runs the next (issue 42, weak: batches)."""

from __future__ import annotations

from types import ModuleType

from robocram.batch import Variant, VariantStatus, project_variants


def test_misbehaving_plans_fail_their_variants_and_keep_the_worker(
    batch_plans: ModuleType,
) -> None:
    hows = ("exit", "interrupt", "unprintable", "")
    variants = [Variant(how or "fine", parameters={"how": how}) for how in hows]
    results = project_variants(variants, plan=batch_plans.misbehave, workers=1).collect()
    by_name = {r.name: r for r in results}
    assert by_name["exit"].failure_type == "SystemExit" and by_name["exit"].message == "3"
    assert by_name["interrupt"].failure_type == "KeyboardInterrupt"
    assert by_name["unprintable"].failure_type == "Unprintable"
    assert by_name["unprintable"].message == "<Unprintable that cannot be shown: ValueError>"
    assert all(by_name[n].status is VariantStatus.FAILED for n in hows[:3])
    assert by_name["fine"].status is VariantStatus.SUCCEEDED
    assert len({r.worker for r in results}) == 1  # one worker ran them all, and lived

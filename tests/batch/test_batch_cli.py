"""``robocram batch`` end to end on examples/batch_tabletop.yaml, its summary, exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from robocram.batch import BatchSummary, VariantResult, VariantStatus
from robocram.cli import EXIT_FAILED, EXIT_INPUT, EXIT_OK, main
from robocram.traces import TraceDatabase, runs

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "batch_tabletop.yaml"


def _row(out: str, label: str) -> list[str]:
    line = next(line for line in out.splitlines() if line.startswith(label))
    return line[len(label) :].split()


def test_the_example_spec_runs_end_to_end(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    db = tmp_path / "batch.db"
    code = main(["batch", str(EXAMPLE), "--workers", "2", "--db", str(db)])
    out = capsys.readouterr().out
    assert out.startswith("6 variants of pick_up for pr2, 2 worker(s) on processes")
    assert _row(out, "variants") == ["6"]
    succeeded = int(_row(out, "succeeded")[0])
    failed, lost = int(_row(out, "failed")[0]), int(_row(out, "lost")[0])
    assert succeeded + failed + lost == 6 and lost == 0
    assert succeeded >= 4  # the mug stays within reach in the example's ranges
    assert code == (EXIT_OK if succeeded == 6 else EXIT_FAILED)
    assert float(_row(out, "median duration [s]")[0]) > 0.0  # it ran (how long is no test)
    with TraceDatabase(db, create=False) as trace:
        stored = runs(trace)
    assert len(stored) == 6
    assert sum(r.status == "succeeded" for r in stored) == succeeded


def test_a_bad_spec_exits_3_naming_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps({"variants": 2, "plan": "pick_up", "robt": "pr2"}), "utf-8")
    assert main(["batch", str(spec)]) == EXIT_INPUT
    err = capsys.readouterr().err
    assert "robt='pr2': not a spec key; use scene, robot, plan" in err
    spec.write_text(json.dumps({"variants": 2}), "utf-8")
    assert main(["batch", str(spec), "--workers", "0"]) == EXIT_INPUT
    assert "workers=0" in capsys.readouterr().err


def test_the_summary_counts_failure_types() -> None:
    results = [
        VariantResult(0, "a", VariantStatus.SUCCEEDED, duration=1.0),
        VariantResult(1, "b", VariantStatus.FAILED, "PerceptionObjectNotFound", duration=3.0),
        VariantResult(2, "c", VariantStatus.FAILED, "IKError", duration=2.0),
        VariantResult(3, "d", VariantStatus.FAILED, "IKError", duration=5.0),
        VariantResult(4, "e", VariantStatus.LOST, "WorkerDied"),
    ]
    summary = BatchSummary.of(results)
    assert (summary.variants, summary.succeeded, summary.failed, summary.lost) == (5, 1, 3, 1)
    assert summary.success_rate == pytest.approx(0.2)
    assert summary.failure_types == (
        ("IKError", 2),
        ("PerceptionObjectNotFound", 1),
        ("WorkerDied", 1),
    )
    assert summary.median_duration == pytest.approx(2.5)  # the lost one did not run
    lines = list(summary.lines())
    assert lines[1].split() == ["succeeded", "1", "(20.0", "%)"]
    assert lines[-3].split() == ["IKError", "2"]

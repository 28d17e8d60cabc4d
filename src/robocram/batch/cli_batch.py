"""``robocram batch SPEC``: run a spec's variants and print what they found.

The command's options are registered by ``robocram.batch_commands``.

Exit codes (those of ``robocram``): 0 every variant succeeded, 1 some failed or were lost
(also when a Ray cluster lost every node: the summary then says what finished, the rest are
``NoWorkerLeft``), 3 the spec or an option cannot be used (the message names the key and the
fix), 130 Ctrl-C (every worker is stopped first).
"""

from __future__ import annotations

import argparse
import sys

from robocram.batch.batch_spec import load_spec
from robocram.batch.batch_summary import BatchSummary
from robocram.batch.errors import BatchError
from robocram.batch.project_variants import project_variants

EXIT_ALL_SUCCEEDED, EXIT_SOME_FAILED, EXIT_BAD_INPUT, EXIT_INTERRUPTED = 0, 1, 3, 130


def run_batch_command(args: argparse.Namespace) -> int:
    """Handle ``robocram batch``; errors of the spec or options are printed, exit code 3."""
    try:
        return _run(args)
    except BatchError as err:
        print(f"robocram: error: {err}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("robocram: interrupted; every worker is stopped", file=sys.stderr)
        return EXIT_INTERRUPTED


def _run(args: argparse.Namespace) -> int:
    spec = load_spec(args.spec)
    workers = args.workers if args.workers is not None else spec.workers or 2
    backend = args.backend or spec.backend or "processes"
    print(
        f"{len(spec.variants)} variants of {getattr(spec.plan, '__name__', spec.plan)} for "
        f"{spec.robot}, {workers} worker(s) on {backend}",
        flush=True,
    )
    run = project_variants(
        spec.variants, spec.plan, spec.robot, spec.scene, workers, backend, traces=args.db
    )
    with run:
        results = run.collect()
    summary = BatchSummary.of(results)
    print("\n".join(summary.lines()))
    if summary.causes:
        print("\n" + "\n".join(summary.cause_lines()))
    if args.db is not None:
        print(f"\nruns traced in {args.db}: robocram runs list {args.db}")
    return EXIT_ALL_SUCCEEDED if summary.succeeded == summary.variants else EXIT_SOME_FAILED

"""``robocram batch SPEC``: the command's options; the batch package loads when it runs.

The handler and its summary live in ``robocram.batch.cli_batch``; registering the command
here keeps the workers, Ray and the physics out of every other command's start-up.
"""

from __future__ import annotations

import argparse
from pathlib import Path


def add_batch_command(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Register ``batch`` among ``robocram``'s subcommands."""
    batch = commands.add_parser(
        "batch",
        help="run a plan's variants from a YAML/JSON spec in parallel worlds, summarise",
        description="Run the variants of a spec (examples/batch_tabletop.yaml) in parallel "
        "projection worlds; print the success rate, failure types and median duration. "
        "Exit 0: all succeeded, 1: some failed or were lost, 3: bad spec or option.",
    )
    batch.add_argument("spec", type=Path, help="a .yaml, .yml or .json batch spec")
    batch.add_argument("--workers", type=int, help="worker processes (default: the spec's, or 2)")
    batch.add_argument(
        "--backend",
        metavar="{processes,ray}",
        help="processes (default) or ray (uses RAY_ADDRESS); another name exits 3",
    )
    batch.add_argument("--db", type=Path, help="write every variant's run to this trace file")
    batch.set_defaults(handler=_run_batch)


def _run_batch(args: argparse.Namespace) -> int:
    from robocram.batch.cli_batch import run_batch_command

    return run_batch_command(args)

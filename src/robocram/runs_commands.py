"""``robocram runs list|show|failures|export|audit``: look into the runs a trace database holds.

Each handler imports the trace store when it runs, so ``robocram --help`` does not load
SQLAlchemy.
"""

from __future__ import annotations

import argparse
import datetime
from pathlib import Path
from typing import TYPE_CHECKING

from robocram.command_exit import EXIT_FAILED, EXIT_OK, CliInputError

if TYPE_CHECKING:
    from robocram.traces import TraceDatabase

DB_HELP = "trace database (SQLite)"


def add_runs_commands(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``runs list|show|failures|export|audit`` to the ``robocram`` parser."""
    runs_parser = commands.add_parser("runs", help="list, show and query stored runs")
    sub = runs_parser.add_subparsers(dest="runs_command", required=True, metavar="ACTION")
    listing = sub.add_parser("list", help="one line per run: id, name, status, counts")
    listing.add_argument("db", type=Path, help=DB_HELP)
    listing.set_defaults(handler=_runs_list)
    show = sub.add_parser("show", help="a run's task tree and its durations per motion")
    show.add_argument("db", type=Path, help=DB_HELP)
    show.add_argument("--run", type=int, help="run id (default: the last run)")
    show.add_argument(
        "--verbose", action="store_true", help="every task and full failure texts, unfolded"
    )
    show.set_defaults(handler=_runs_show)
    fails = sub.add_parser("failures", help="failures where they were raised, by type")
    fails.add_argument("db", type=Path, help=DB_HELP)
    fails.add_argument("--type", dest="failure_type", help="only this failure type")
    fails.add_argument("--run", type=int, help="only this run")
    fails.set_defaults(handler=_runs_failures)
    export = sub.add_parser("export", help="write a run as ROS 2 messages (TF, joints, poses)")
    export.add_argument("db", type=Path, help=DB_HELP)
    export.add_argument("--run", type=int, help="run id (default: the last run)")
    export.add_argument("--mcap", type=Path, required=True, help="the MCAP file to write")
    _robot_file_option(export)
    export.set_defaults(handler=_runs_export)
    audit = sub.add_parser(
        "audit",
        help="replay stored trajectories densely: penetrations, limits, jumps (exit 1 if any)",
    )
    audit.add_argument("db", type=Path, help=DB_HELP)
    audit.add_argument("--run", type=int, help="only this run (default: every run)")
    _robot_file_option(audit)
    audit.set_defaults(handler=_runs_audit)


def _robot_file_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--robot-file",
        type=Path,
        action="append",
        default=[],
        metavar="FILE.py",
        help="a robot's description file, if it moved since the run (repeatable; the "
        "trace names the file each robot ran with)",
    )


def robot_files(paths: list[Path]) -> dict[str, str]:
    """Description files by the name of the robot each describes."""
    from robocram.robots.description_source import description_from

    found = {}
    for path in paths:
        if path.suffix != ".py":
            raise CliInputError(
                f"--robot-file {path}: give the .py file that defines description()"
            )
        found[description_from(str(path)).name] = str(path)
    return found


def open_database(path: Path) -> TraceDatabase:
    """An existing trace database; TraceError if ``path`` is none."""
    from robocram.traces import TraceDatabase

    return TraceDatabase(path, create=False)


def last_run(db: TraceDatabase, run: int | None) -> int:
    """``run`` if the database holds it, else (None) its last run's id."""
    from robocram.traces import require_run, runs

    if run is not None:
        return require_run(db, run).id
    stored = runs(db)
    if not stored:
        raise CliInputError(f"{db.path} holds no runs yet; record one with `robocram demo --db`")
    return stored[-1].id


def _when(stamp: float | None) -> str:
    if stamp is None:
        return "-"
    return datetime.datetime.fromtimestamp(stamp, datetime.UTC).strftime("%Y-%m-%d %H:%M:%S")


def _runs_list(args: argparse.Namespace) -> int:
    from robocram.traces import runs

    with open_database(args.db) as db:
        stored = runs(db)
    print(f"{'run':>5}  {'name':<20} {'status':<10} {'started (UTC)':<19} tasks failed states")
    for r in stored:
        print(
            f"{r.id:>5}  {r.name[:20]:<20} {r.status:<10} {_when(r.start):<19} "
            f"{r.tasks:>5} {r.failed_tasks:>6} {r.world_states:>6}"
        )
    return EXIT_OK


def _runs_show(args: argparse.Namespace) -> int:
    from robocram.execution.tree_text import tree_text
    from robocram.traces import durations, task_tree

    with open_database(args.db) as db:
        run = last_run(db, args.run)
        tree = task_tree(db, run)
        stats = durations(db, run)
    print(f"run {run}:")
    print(tree_text(tree, verbose=args.verbose))
    if stats:
        print("\nduration per performed designator type:")
        for name, s in sorted(stats.items()):
            print(
                f"  {name:<32} n={s.count:<3} "
                f"mean {s.mean * 1e3:8.1f} ms  max {s.max * 1e3:8.1f} ms"
            )
    return EXIT_OK


def _runs_failures(args: argparse.Namespace) -> int:
    from robocram.traces import failures

    with open_database(args.db) as db:
        if args.run is not None:
            last_run(db, args.run)  # an unknown run is bad input, not "no failures"
        found = failures(db, args.failure_type, args.run)
    if not found:
        where = f"run {args.run}" if args.run is not None else str(args.db)
        kind = f" of type {args.failure_type}" if args.failure_type else ""
        print(f"no failures{kind} in {where}")
        return EXIT_OK
    counts: dict[str, int] = {}
    for f in found:
        counts[f.type] = counts.get(f.type, 0) + 1
    for name, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"{n:>5}  {name}")
    for f in found:
        print(f"run {f.run}  {f.path}\n       {f.type}: {f.message}")
    return EXIT_OK


def _runs_export(args: argparse.Namespace) -> int:
    from robocram.traces.mcap_export import export_mcap

    with open_database(args.db) as db:
        run = last_run(db, args.run)
        count = export_mcap(db, run, args.mcap, robots=robot_files(args.robot_file))
    print(f"wrote {count} messages of run {run} to {args.mcap} (/tf, /joint_states, /object_poses)")
    return EXIT_OK


def _runs_audit(args: argparse.Namespace) -> int:
    from robocram.traces.trajectory_audit import audit_runs

    with open_database(args.db) as db:
        report = audit_runs(db, args.run, robots=robot_files(args.robot_file))
    for finding in report.findings:
        print(finding.line())
    print("\n".join(report.summary_lines()))
    return EXIT_OK if report.clean else EXIT_FAILED

"""``robocram``: run the demo, look into stored runs, export, view and replay them.

Exit codes: 0 done; 1 the plan failed, a batch had variants that failed, or the robot check
found problems (missing meshes); 2 wrong usage; 3 bad input (a file that is not a trace
database, an unknown run, an unreadable URDF, a port in use, a missing optional package, a
bad batch spec).
"""

from __future__ import annotations

import argparse
import contextlib
import datetime
import os
import socket
import sys
import time
import warnings
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from robocram.batch.cli_batch import add_batch_command
from robocram.environment_commands import add_environment_commands
from robocram.execution import PlanFailure, TaskSnapshot
from robocram.robot_commands import add_robot_commands
from robocram.robots import DescriptionError, MissingMeshWarning, RobotModel, load_description
from robocram.scenes import SceneError
from robocram.traces import (
    TRACE_ENV,
    TraceDatabase,
    TraceError,
    durations,
    failures,
    require_run,
    runs,
    task_tree,
)
from robocram.traces.mcap_export import export_mcap

EXIT_OK, EXIT_FAILED, EXIT_USAGE, EXIT_INPUT = 0, 1, 2, 3
ROBOT_HELP = (
    "a built-in robot (pr2, hsrb, boxy), a description file (my_robot.py, as `robocram robot "
    "draft` writes it) or pkg.module:NAME (default: %(default)s)"
)

try:
    from robocram.viewer.errors import ViewerError as _ViewerError
except ImportError:  # the viewer extra is not installed; its commands say so

    class _ViewerError(Exception):  # type: ignore[no-redef]
        """Stands in for robocram.viewer's root error."""


class CliInputError(Exception):
    """Input the command cannot work with; the message says what to do instead."""


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (default: ``sys.argv[1:]``); return the exit code."""
    args = _parser().parse_args(argv)
    try:
        return int(args.handler(args))
    except (TraceError, DescriptionError, SceneError, CliInputError, _ViewerError) as err:
        print(f"robocram: error: {err}", file=sys.stderr)
        return EXIT_INPUT


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="robocram",
        description="CRAM in Python: run plans in projection, keep and inspect their traces.",
        epilog="exit codes: 0 done, 1 plan failed / batch variants failed / robot check found "
        "problems, 2 usage error, 3 bad input (database, run id, URDF, port, missing package, "
        "batch spec)",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    demo = commands.add_parser("demo", help="a robot picks up a mug in projection")
    demo.add_argument("--robot", default="pr2", help=ROBOT_HELP)
    demo.add_argument(
        "--db", type=Path, help=f"trace the run into this SQLite file (or ${TRACE_ENV})"
    )
    demo.set_defaults(handler=_demo)
    _add_runs_commands(commands)
    _add_viewer_commands(commands)
    add_batch_command(commands)
    check = commands.add_parser("check-robot", help="read a URDF (or built-in robot) and report")
    check.add_argument("urdf", help="a URDF file, or a built-in robot name such as pr2")
    check.set_defaults(handler=_check_robot)
    add_robot_commands(commands)
    add_environment_commands(commands)
    return parser


def _add_runs_commands(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    runs_parser = commands.add_parser("runs", help="list, show and query stored runs")
    sub = runs_parser.add_subparsers(dest="runs_command", required=True, metavar="ACTION")
    listing = sub.add_parser("list", help="one line per run: id, name, status, counts")
    listing.add_argument("db", type=Path, help="trace database (SQLite)")
    listing.set_defaults(handler=_runs_list)
    show = sub.add_parser("show", help="a run's task tree and its durations per motion")
    show.add_argument("db", type=Path, help="trace database (SQLite)")
    show.add_argument("--run", type=int, help="run id (default: the last run)")
    show.set_defaults(handler=_runs_show)
    fails = sub.add_parser("failures", help="failures where they were raised, by type")
    fails.add_argument("db", type=Path, help="trace database (SQLite)")
    fails.add_argument("--type", dest="failure_type", help="only this failure type")
    fails.add_argument("--run", type=int, help="only this run")
    fails.set_defaults(handler=_runs_failures)
    export = sub.add_parser("export", help="write a run as ROS 2 messages (TF, joints, poses)")
    export.add_argument("db", type=Path, help="trace database (SQLite)")
    export.add_argument("--run", type=int, help="run id (default: the last run)")
    export.add_argument("--mcap", type=Path, required=True, help="the MCAP file to write")
    export.set_defaults(handler=_runs_export)


def _add_viewer_commands(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    view = commands.add_parser("view", help="live demo: watch a pick-up in the browser viewer")
    view.add_argument("--robot", default="pr2", help=ROBOT_HELP)
    view.add_argument(
        "--no-wait", action="store_true", help="start the plan at once, not at the first browser"
    )
    view.add_argument(
        "--speed", type=float, default=1.0, help="motions play at this many times their pace"
    )
    replay = commands.add_parser("replay", help="a stored run in the browser viewer")
    replay.add_argument("db", type=Path, help="trace database (SQLite)")
    replay.add_argument("--run", type=int, help="run id (default: the last run)")
    for command, handler in ((view, _view), (replay, _replay)):
        command.add_argument(
            "--host", default="127.0.0.1", help="address to bind (default: %(default)s)"
        )
        command.add_argument("--port", type=int, default=8080, help="port (default: %(default)s)")
        command.add_argument(
            "--screenshot", type=Path, help="save a PNG from headless Chromium, exit"
        )
        command.add_argument("--seconds", type=float, help="serve this long [s], then exit")
        command.set_defaults(handler=handler)


def _check_address(host: str, port: int) -> None:
    """Refuse a port out of range or an address this machine does not have, before serving."""
    if not 1 <= port <= 65535:
        raise CliInputError(f"--port {port} is out of range; give a port in 1..65535")
    try:
        infos = socket.getaddrinfo(host, None, type=socket.SOCK_STREAM)
        family, _, _, _, address = infos[0]
        with socket.socket(family, socket.SOCK_STREAM) as probe:
            probe.bind((address[0], 0))  # any free port: only the address is tested
    except OSError as err:
        raise CliInputError(
            f"--host {host} is not an address of this machine ({err.strerror or err}); "
            "use 127.0.0.1 (this machine only) or 0.0.0.0 (every interface)"
        ) from err


def _view(args: argparse.Namespace) -> int:
    """Serve the viewer, wait for a browser (or --no-wait), then run the pick-up live."""
    from robocram.designators import a
    from robocram.execution import listening, perform
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.scenes import tabletop_scene

    _check_address(args.host, args.port)
    if not args.speed > 0.0:
        raise CliInputError(f"--speed {args.speed} must be positive, e.g. 1 (the robot's pace)")
    viewer_module = _viewer_module()
    scene = tabletop_scene(args.robot)
    try:
        with (
            viewer_module.Viewer(scene.world, args.host, args.port, "robocram view") as viewer,
            contextlib.ExitStack() as page,
        ):
            print(f"viewer at {viewer.url}", flush=True)
            browser = None
            if args.screenshot is not None:  # the picture's browser is the one waited for
                from robocram.viewer.page_picture import picture_page

                browser = page.enter_context(picture_page(viewer))
            if not args.no_wait:
                print("waiting for a browser to open the page (--no-wait: start now)", flush=True)
                viewer.wait_for_browser()
            try:
                with (
                    viewer_module.LiveFeed(viewer, scene.world, args.speed) as feed,
                    listening(feed),
                    simulated_robot(scene.world, scene.robot, name="pick-mug"),
                ):
                    stand = a.location(reachable_for=scene.robot, object="mug-1")  # costmap
                    perform(a.motion(type="going", target=stand))
                    pick_up(scene.look_target)
            except PlanFailure as failure:
                print(f"the plan failed: {type(failure).__name__}: {failure}", file=sys.stderr)
            if browser is not None:
                from robocram.viewer.page_picture import save_picture

                print(f"wrote {save_picture(browser, args.screenshot)}")
                return EXIT_OK
            return _serve(viewer, args)
    finally:
        scene.world.close()


def _replay(args: argparse.Namespace) -> int:
    _check_address(args.host, args.port)
    viewer_module = _viewer_module()
    with _open(args.db) as db:
        run = _last_run(db, args.run)
        viewer = viewer_module.replay_viewer(db, run, args.host, args.port)
    with viewer:
        print(f"run {run} at {viewer.url}", flush=True)
        return _serve(viewer, args)


def _viewer_module() -> Any:
    try:
        import robocram.viewer as viewer_module
    except ImportError as err:
        raise CliInputError(
            f"the viewer needs {err.name!r}: pip install 'robocram[viewer]'"
        ) from err
    return viewer_module


def _serve(viewer: Any, args: argparse.Namespace) -> int:
    if args.screenshot is not None:
        from robocram.viewer.page_picture import take_picture

        take_picture(viewer, args.screenshot)
        print(f"wrote {args.screenshot}")
        return EXIT_OK
    print("serving; press Ctrl-C to stop", flush=True)
    with contextlib.suppress(KeyboardInterrupt):
        time.sleep(args.seconds if args.seconds is not None else 10**9)
    return EXIT_OK


def _open(path: Path) -> TraceDatabase:
    return TraceDatabase(path, create=False)


def _demo(args: argparse.Namespace) -> int:
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.scenes import tabletop_scene
    from robocram.traces import trace_from_environment, trace_to

    scene = tabletop_scene(args.robot)
    tracing = trace_to(args.db, scene.world) if args.db else trace_from_environment(scene.world)
    try:
        with tracing as tracer, simulated_robot(scene.world, scene.robot, name="pick-mug") as run:
            pick_up(scene.look_target)
    except PlanFailure as failure:
        print(f"the plan failed: {type(failure).__name__}: {failure}", file=sys.stderr)
        return EXIT_FAILED
    finally:
        scene.world.close()
    print(run.tree.render())
    if tracer is not None:
        print(f"\ntraced as run {tracer.runs[-1]} in {tracer.db.path}")
    return EXIT_OK


def _when(stamp: float | None) -> str:
    if stamp is None:
        return "-"
    return datetime.datetime.fromtimestamp(stamp, datetime.UTC).strftime("%Y-%m-%d %H:%M:%S")


def _runs_list(args: argparse.Namespace) -> int:
    with _open(args.db) as db:
        stored = runs(db)
    print(f"{'run':>5}  {'name':<20} {'status':<10} {'started (UTC)':<19} tasks failed states")
    for r in stored:
        print(
            f"{r.id:>5}  {r.name[:20]:<20} {r.status:<10} {_when(r.start):<19} "
            f"{r.tasks:>5} {r.failed_tasks:>6} {r.world_states:>6}"
        )
    return EXIT_OK


def _last_run(db: TraceDatabase, run: int | None) -> int:
    if run is not None:
        return require_run(db, run).id
    stored = runs(db)
    if not stored:
        raise CliInputError(f"{db.path} holds no runs yet; record one with `robocram demo --db`")
    return stored[-1].id


def _runs_show(args: argparse.Namespace) -> int:
    with _open(args.db) as db:
        run = _last_run(db, args.run)
        tree = task_tree(db, run)
        stats = durations(db, run)
    print(f"run {run}:")
    print("\n".join(render_tree(tree)))
    if stats:
        print("\nduration per performed designator type:")
        for name, s in sorted(stats.items()):
            print(
                f"  {name:<32} n={s.count:<3} "
                f"mean {s.mean * 1e3:8.1f} ms  max {s.max * 1e3:8.1f} ms"
            )
    return EXIT_OK


def render_tree(snapshot: TaskSnapshot, indent: str = "") -> Iterator[str]:
    """A stored task tree as text lines, like the live tree's ``render()``."""
    if not indent:
        yield snapshot.label()
    for i, child in enumerate(snapshot.children):
        last = i == len(snapshot.children) - 1
        yield f"{indent}{'└── ' if last else '├── '}{child.label()}"
        yield from (
            render_tree(child, indent + ("    " if last else "│   ")) if child.children else ()
        )


def _runs_failures(args: argparse.Namespace) -> int:
    with _open(args.db) as db:
        found = failures(db, args.failure_type, args.run)
    counts: dict[str, int] = {}
    for f in found:
        counts[f.type] = counts.get(f.type, 0) + 1
    for name, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"{n:>5}  {name}")
    for f in found:
        print(f"run {f.run}  {f.path}\n       {f.type}: {f.message}")
    return EXIT_OK


def _runs_export(args: argparse.Namespace) -> int:
    with _open(args.db) as db:
        run = _last_run(db, args.run)
        count = export_mcap(db, run, args.mcap)
    print(f"wrote {count} messages of run {run} to {args.mcap} (/tf, /joint_states, /object_poses)")
    return EXIT_OK


def _check_robot(args: argparse.Namespace) -> int:
    path = Path(args.urdf)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", MissingMeshWarning)
        if path.suffix != ".urdf" and not path.exists():
            model = load_description(args.urdf).model
            assert model is not None  # load_description reads it
        elif not path.is_file():
            raise CliInputError(f"no URDF file at {path}; give a .urdf path or a built-in robot")
        else:
            model = RobotModel.from_file(path)
    movable = [j for j in model.joints.values() if j.type != "fixed"]
    print(
        f"{model.name}: {len(model.links)} links, {len(model.joints)} joints "
        f"({len(movable)} movable)"
    )
    problems = [str(w.message) for w in caught if issubclass(w.category, MissingMeshWarning)]
    for problem in problems:
        print(f"  {problem}")
    return EXIT_FAILED if problems else EXIT_OK


def run(fn: Callable[[Sequence[str] | None], int] = main) -> None:
    """Console-script entry point: exit with the command's code."""
    sys.exit(fn(sys.argv[1:]))


if __name__ == "__main__":
    os.environ.setdefault("PYTHONUNBUFFERED", "1")
    run()

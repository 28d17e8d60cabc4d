"""``robocram``: run the demo, look into stored runs, export, view and replay them.

Exit codes: 0 done; 1 the plan failed, a batch had variants that failed, the robot check
found problems (missing meshes) or a run's audit found something; 2 wrong usage; 3 bad
input (a file that is not a trace database, an unknown run, an unreadable URDF, a port in
use, a missing optional package, a bad batch spec).
"""

from __future__ import annotations

import argparse
import contextlib
import os
import socket
import sys
import time
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from robocram.batch_commands import add_batch_command
from robocram.command_exit import (
    EXIT_FAILED,
    EXIT_INPUT,
    EXIT_OK,
    EXIT_USAGE,
    CliInputError,
    is_input_error,
)
from robocram.environment_commands import add_environment_commands
from robocram.robot_commands import add_robot_commands
from robocram.runs_commands import add_runs_commands, last_run, open_database

__all__ = ["CliInputError", "EXIT_FAILED", "EXIT_INPUT", "EXIT_OK", "EXIT_USAGE", "main", "run"]

TRACE_ENV = "ROBOCRAM_TRACE"  # robocram.traces.TRACE_ENV, named so --help loads no trace store
ROBOT_HELP = (
    "a built-in robot (pr2, hsrb, boxy), a description file (my_robot.py, as `robocram robot "
    "draft` writes it) or pkg.module:NAME (default: %(default)s)"
)
VERBOSE_HELP = "print every task of the tree and full failure texts, unfolded"


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (default: ``sys.argv[1:]``); return the exit code."""
    args = _parser().parse_args(argv)
    try:
        return int(args.handler(args))
    except Exception as err:
        if not is_input_error(err):
            raise
        print(f"robocram: error: {err}", file=sys.stderr)
        return EXIT_INPUT


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="robocram",
        description="CRAM in Python: run plans in projection, keep and inspect their traces.",
        epilog="exit codes: 0 done, 1 plan failed / batch variants failed / robot check found "
        "problems / a run's audit found something, 2 usage error, 3 bad input (database, run "
        "id, URDF, port, missing package, batch spec)",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    demo = commands.add_parser("demo", help="a robot picks up a mug in projection")
    demo.add_argument("--robot", default="pr2", help=ROBOT_HELP)
    demo.add_argument(
        "--activity", choices=("breakfast",),
        help="an everyday activity instead: breakfast sets the table for two and clears it "
        "(traced to --db or out/breakfast.db; out/breakfast_set.png rendered from the trace)",
    )  # fmt: skip
    demo.add_argument(
        "--db", type=Path, help=f"trace the run into this SQLite file (or ${TRACE_ENV})"
    )
    demo.add_argument("--verbose", action="store_true", help=VERBOSE_HELP)
    demo.set_defaults(handler=_demo)
    add_runs_commands(commands)
    _add_viewer_commands(commands)
    add_batch_command(commands)
    check = commands.add_parser("check-robot", help="read a URDF (or built-in robot) and report")
    check.add_argument("urdf", help="a URDF file, or a built-in robot name such as pr2")
    check.set_defaults(handler=_check_robot)
    add_robot_commands(commands)
    add_environment_commands(commands)
    return parser


def _add_viewer_commands(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    view = commands.add_parser("view", help="live demo: watch a pick-up in the browser viewer")
    view.add_argument("--robot", default="pr2", help=ROBOT_HELP)
    view.add_argument(
        "--no-wait", action="store_true", help="start the plan at once, not at the first browser"
    )
    view.add_argument(
        "--speed", type=float, default=1.0, help="motions play at this many times their pace"
    )
    view.add_argument(
        "--dwell",
        type=float,
        help="each state stays on the page this long [s] before the plan goes on "
        "(default: the viewer's DWELL, 0.3)",
    )
    view.add_argument(
        "--push-rate",
        type=float,
        help="at most this many pushes to the page a second [Hz] (default: the viewer's "
        "MAX_PUSH_RATE, 5)",
    )
    view.add_argument(
        "--play-period",
        type=float,
        help="a motion is played one frame every this much of its time [s] (default: the "
        "viewer's REPLAY_PERIOD, 0.1)",
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
        command.add_argument(
            "--no-environment-map",
            action="store_true",
            help="light the scene without its environment map: a page drawn without a GPU "
            "(software WebGL) loads seconds sooner",
        )
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
    from robocram.execution import PlanFailure, listening, perform
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.scenes import tabletop_scene

    _check_address(args.host, args.port)
    if not args.speed > 0.0:
        raise CliInputError(f"--speed {args.speed} must be positive, e.g. 1 (the robot's pace)")
    if args.dwell is not None and not args.dwell >= 0.0:
        raise CliInputError(f"--dwell {args.dwell} must be 0 or more seconds, e.g. 0.3")
    if args.push_rate is not None and not args.push_rate > 0.0:
        raise CliInputError(f"--push-rate {args.push_rate} must be positive, e.g. 5 [Hz]")
    if args.play_period is not None and not args.play_period > 0.0:
        raise CliInputError(f"--play-period {args.play_period} must be positive, e.g. 0.1 [s]")
    pacing = {"dwell": args.dwell, "push_rate": args.push_rate, "play_period": args.play_period}
    viewer_module = _viewer_module()
    scene = tabletop_scene(args.robot)
    try:
        with (
            viewer_module.Viewer(
                scene.world,
                args.host,
                args.port,
                "robocram view",
                environment_map=not args.no_environment_map,
            ) as viewer,
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
                    viewer_module.LiveFeed(
                        viewer,
                        scene.world,
                        args.speed,
                        **{name: value for name, value in pacing.items() if value is not None},
                    ) as feed,
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
    with open_database(args.db) as db:
        run = last_run(db, args.run)
        viewer = viewer_module.replay_viewer(
            db, run, args.host, args.port, environment_map=not args.no_environment_map
        )
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


def _activity_demo(args: argparse.Namespace) -> int:
    from robocram.activity_demo import run_breakfast

    out = Path("out")
    done = run_breakfast(args.robot, args.db or out / "breakfast.db", out, args.verbose)
    print(f"\ntraced as run {done.run} in {done.db}; the set table: {done.picture}")
    return EXIT_FAILED if done.failures else EXIT_OK


def _demo(args: argparse.Namespace) -> int:
    if args.activity is not None:
        return _activity_demo(args)
    from robocram.execution import PlanFailure
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
    print(run.tree.render(verbose=args.verbose))
    if tracer is not None:
        print(f"\ntraced as run {tracer.runs[-1]} in {tracer.db.path}")
    return EXIT_OK


def _check_robot(args: argparse.Namespace) -> int:
    from robocram.robots import MissingMeshWarning, RobotModel, load_description

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

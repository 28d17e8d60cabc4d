"""``make demo``: in the kitchen, a PR2 in projection carries a mug and a bowl to the table.

Builds the kitchen scene, performs two ``transporting`` action designators inside
``simulated_robot`` (the mug from the north counter; the bowl out of the top drawer, which
the search opens and the transport closes again), prints the task tree and writes
``out/demo_before.png`` and ``out/demo_after.png``. The run is traced to a fresh
``out/demo.db`` (``robocram replay out/demo.db`` shows it), and ``out/demo.gif`` is rendered
from that trace: the stored trajectories, seen from the pictures' viewpoint. The tabletop
pick-up demo lives on as ``examples/pick_mug.py``. Another robot's files go to
``out/<robot>/``; a transport that fails is one line after the tree, and the demo goes on
(the exit code is 1).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from robocram.designators import a, an
from robocram.execution import PlanFailure
from robocram.plans import perform
from robocram.projection import looking_orientation, simulated_robot
from robocram.robots import is_description_spec
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.traces import animate_run, trace_to
from robocram.world import World

VIEW_FROM = (2.4, -2.2, 3.3)  # [m] in map, where the pictures are taken from
VIEW_AT = (-0.7, 0.3, 0.4)  # [m] in map, what they look at
TABLE = ("kitchen", "table_top")
ITEMS = (("mug", "mug-1"), ("bowl", "bowl-1"))  # (type searched for, item placed for)
MAX_REASON = 200  # characters of a failure's message on its one line
GIF_SIZE = (480, 360)  # [px], with the camera following the robot: the drawer it opens shows


CAMERA = Pose(VIEW_FROM, looking_orientation(VIEW_FROM, VIEW_AT))


def picture(world: World, path: Path) -> Path:
    """Render the kitchen from :data:`VIEW_FROM` into ``path``."""
    return world.view.save_png(path, CAMERA, width=800, height=600)


def fresh_database(path: Path) -> Path:
    """``path`` with no trace database left from an earlier demo (its WAL files too)."""
    for old in (path, path.with_name(path.name + "-wal"), path.with_name(path.name + "-shm")):
        old.unlink(missing_ok=True)
    return path


@dataclass(frozen=True)
class DemoRun:
    """What the demo wrote, and one line per transport that failed."""

    written: list[Path]
    failures: list[str]


def output_folder(out_dir: Path, robot: str, name: str) -> Path:
    """Where a robot's demo files go: ``out_dir`` for the PR2 (as the README says),
    ``out_dir/<name>`` for any other, so two robots' runs never mix."""
    return out_dir if robot == "pr2" else out_dir / name


def main(out_dir: Path = Path("out"), robot: str = "pr2", verbose: bool = False) -> list[Path]:
    """Run both transports, print the task tree, write and return the pictures and the GIF.

    ``robot`` is a built-in robot's name or a description file (``my_robot.py``); the tree
    folds the tries the plan recovered from unless ``verbose``.
    """
    return run_demo(out_dir, robot, verbose).written


@dataclass(frozen=True)
class Retries:
    """How many stands fetching and delivering try (None: the plans' defaults)."""

    stand: int | None = None
    place: int | None = None

    def keys(self) -> dict[str, int]:
        """The transporting designator's keys for the retries that are set."""
        given = {"stand_retries": self.stand, "place_retries": self.place}
        return {key: value for key, value in given.items() if value is not None}


def run_demo(
    out_dir: Path = Path("out"),
    robot: str = "pr2",
    verbose: bool = False,
    retries: Retries = Retries(),  # noqa: B008 - frozen
) -> DemoRun:
    """:func:`main`, keeping going past a failed transport: its reason is printed on one
    line after the task tree, and the pictures and the GIF show what was done. The GIF
    is rendered with the robot as it ran: a description file is read again from its path."""
    start = time.perf_counter()
    scene = kitchen_scene(robot)
    world = scene.world
    description = world.robot(scene.robot).description
    out_dir = output_folder(out_dir, robot, description.name)
    out_dir.mkdir(parents=True, exist_ok=True)
    pictures = [picture(world, out_dir / "demo_before.png")]
    db_path = fresh_database(out_dir / "demo.db")
    failures: list[str] = []
    with (
        trace_to(db_path, world=world) as tracer,
        simulated_robot(world, scene.robot, name="kitchen-transport") as run,
    ):
        for kind, item in ITEMS:
            target = a.location(on=TABLE, for_=item)
            try:
                perform(
                    an.action(type="transporting", object=kind, target=target, **retries.keys())
                )
            except PlanFailure as failure:
                failures.append(f"the {kind} was not transported: {one_line(failure)}")
    print(run.tree.render(verbose=verbose))
    for line in failures:
        print(line)
    for _, item in ITEMS:
        x, y, z = world.pose(item).position
        links = sorted({p.link_b for p in world.contacts.contact_points(item, "kitchen")})
        where = f"rests on {', '.join(links)} at" if links else "is at"
        print(f"{item} {where} ({x:.2f}, {y:.2f}, {z:.2f}) m in map")
    pictures.append(picture(world, out_dir / "demo_after.png"))
    world.close()
    files = {description.name: robot} if is_description_spec(robot) else {}
    gif = animate_run(  # framed on the robot: the drawer's handle shows in the picture
        db_path, tracer.runs[-1], out_dir / "demo.gif", width=GIF_SIZE[0],
        height=GIF_SIZE[1], robots=files,
    )  # fmt: skip
    print(
        f"traced to {db_path}; {gif.path}: {gif.frames} frames over {gif.replay_duration:.1f} s "
        f"of motion, {gif.size / 1e6:.2f} MB in {gif.render_seconds:.1f} s"
    )
    pictures.append(gif.path)
    print(f"wrote {', '.join(str(p) for p in pictures)} in {time.perf_counter() - start:.2f} s")
    return DemoRun(pictures, failures)


def one_line(failure: PlanFailure) -> str:
    """The failure's type and the start of its message, on one line (the tree has more)."""
    text = " ".join(str(failure).split())
    cut = text if len(text) <= MAX_REASON else text[: MAX_REASON - 3].rstrip() + "..."
    return f"{type(failure).__name__}: {cut}"


def command_line(argv: Sequence[str] | None = None) -> list[Path]:
    """``python -m robocram.demo [--robot ROBOT] [--out DIR] [--verbose]`` (``make demo``)."""
    parser = argparse.ArgumentParser(prog="python -m robocram.demo", description=__doc__)
    parser.add_argument(
        "--robot",
        default="pr2",
        help="a built-in robot (pr2, hsrb, boxy) or a description file (my_robot.py)",
    )
    parser.add_argument("--out", type=Path, default=Path("out"), help="where the pictures go")
    parser.add_argument(
        "--verbose", action="store_true", help="print every task and full failure texts"
    )
    parser.add_argument(
        "--stand-retries",
        type=_count,
        help="stands fetching and delivering try before giving up (default: the plans' 3)",
    )
    parser.add_argument(
        "--place-retries", type=_count, help="placing spots delivering tries (default: 6)"
    )
    args = parser.parse_args(argv)
    retries = Retries(args.stand_retries, args.place_retries)
    done = run_demo(args.out, args.robot, args.verbose, retries)
    if done.failures:
        raise SystemExit(1)
    return done.written


def _count(text: str) -> int:
    """A retry count from the command line: a whole number of at least 1."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is no count; give a whole number >= 1")
    return value


if __name__ == "__main__":
    command_line()

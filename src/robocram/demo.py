"""``make demo``: in the kitchen, a PR2 in projection carries a mug and a bowl to the table.

Builds the kitchen scene, performs two ``transporting`` action designators inside
``simulated_robot`` (the mug from the north counter; the bowl out of the top drawer, which
the search opens and the transport closes again), prints the task tree and writes
``out/demo_before.png`` and ``out/demo_after.png``. The run is traced to a fresh
``out/demo.db`` (``robocram replay out/demo.db`` shows it), and ``out/demo.gif`` is rendered
from that trace: the stored trajectories, seen from the pictures' viewpoint. The tabletop
pick-up demo lives on as ``examples/pick_mug.py``.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Sequence
from pathlib import Path

from robocram.designators import a, an
from robocram.plans import perform
from robocram.projection import looking_orientation, simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.traces import animate_run, trace_to
from robocram.world import World

VIEW_FROM = (2.4, -2.2, 3.3)  # [m] in map, where the pictures are taken from
VIEW_AT = (-0.7, 0.3, 0.4)  # [m] in map, what they look at
TABLE = ("kitchen", "table_top")
ITEMS = (("mug", "mug-1"), ("bowl", "bowl-1"))  # (type searched for, item placed for)


CAMERA = Pose(VIEW_FROM, looking_orientation(VIEW_FROM, VIEW_AT))


def picture(world: World, path: Path) -> Path:
    """Render the kitchen from :data:`VIEW_FROM` into ``path``."""
    return world.save_png(path, CAMERA, width=800, height=600)


def fresh_database(path: Path) -> Path:
    """``path`` with no trace database left from an earlier demo (its WAL files too)."""
    for old in (path, path.with_name(path.name + "-wal"), path.with_name(path.name + "-shm")):
        old.unlink(missing_ok=True)
    return path


def main(out_dir: Path = Path("out"), robot: str = "pr2", verbose: bool = False) -> list[Path]:
    """Run both transports, print the task tree, write and return the pictures and the GIF.

    ``robot`` is a built-in robot's name or a description file (``my_robot.py``); the tree
    folds the tries the plan recovered from unless ``verbose``.
    """
    start = time.perf_counter()
    scene = kitchen_scene(robot)
    world = scene.world
    out_dir.mkdir(parents=True, exist_ok=True)
    pictures = [picture(world, out_dir / "demo_before.png")]
    db_path = fresh_database(out_dir / "demo.db")
    with (
        trace_to(db_path, world=world) as tracer,
        simulated_robot(world, scene.robot, name="kitchen-transport") as run,
    ):
        for kind, item in ITEMS:
            target = a.location(on=TABLE, for_=item)
            perform(an.action(type="transporting", object=kind, target=target))
    print(run.tree.render(verbose=verbose))
    for _, item in ITEMS:
        x, y, z = world.pose(item).position
        links = sorted({p.link_b for p in world.contact_points(item, "kitchen")})
        print(f"{item} rests on {', '.join(links)} at ({x:.2f}, {y:.2f}, {z:.2f}) m in map")
    pictures.append(picture(world, out_dir / "demo_after.png"))
    world.close()
    gif = animate_run(db_path, tracer.runs[-1], out_dir / "demo.gif", CAMERA)
    print(
        f"traced to {db_path}; {gif.path}: {gif.frames} frames over {gif.replay_duration:.1f} s "
        f"of motion, {gif.size / 1e6:.2f} MB in {gif.render_seconds:.1f} s"
    )
    pictures.append(gif.path)
    print(f"wrote {', '.join(str(p) for p in pictures)} in {time.perf_counter() - start:.2f} s")
    return pictures


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
    args = parser.parse_args(argv)
    return main(args.out, args.robot, args.verbose)


if __name__ == "__main__":
    command_line()

"""The robot zoo: every robot of a corpus through draft, check, pick-up and a transport.

Run: ``.venv/bin/python benchmarks/robot_zoo.py [--only NAME ...] [--timeout S] [--out DIR]``.
Each robot goes through the same steps with default settings and no edits:

1. **draft**: ``draft_description(urdf)`` written as a module (built-in robots and the
   kept description files skip it: they are drafts already, held to them by the tests);
2. **check**: ``check_robot`` must pass every check;
3. **pick-up**: ``pick_up`` in the tabletop scene lifts the mug;
4. **mug**, **bowl**: the kitchen transport of the mug from the counter, then of the bowl
   from its drawer, to the table (as ``make demo`` does); for a robot whose base is fixed
   (a lone arm, a fixed station), which no kitchen transport fits, instead
4. **workcell**: the same ``transport`` action carries the mug, then the bowl, to other
   spots of its table (``workcell_scene``: the table placed from its reach, as the
   tabletop scene's), the robot standing where it is mounted.

Each robot runs in a process of its own with a time limit. The table printed at the end
says, per robot, the last step reached, the seconds it took and, where it stopped, one
line saying why (the check's first failure and its fix, or the plan's failure); its
summary counts the robots complete with the kitchen and those complete with every step
that applies to them (the workcell, for a fixed base). The
corpus: the built-in manipulators, ``examples/robots``, the Stretch and Fetch kept in
``tests/data``, the mobile manipulators and arms of ``example-robot-data``, and the public
robots kept in ``tests/data/zoo`` (their sources and licences beside them). No network.
"""

from __future__ import annotations

import argparse
import multiprocessing
import sys
import time
import traceback
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robocram.scenes.kitchen_scene import KitchenScene

ROOT = Path(__file__).resolve().parents[1]
STEPS = ("draft", "check", "pick-up", "mug", "bowl")
FIXED_STEPS = ("draft", "check", "pick-up", "workcell")  # a base that is fixed: no kitchen
REASON_WIDTH = 160  # characters of the one-line reason


@dataclass(frozen=True)
class ZooRobot:
    """One robot of the corpus: a built-in name, a description file or a URDF to draft."""

    name: str
    source: str  # "pr2", "path/to/file.py" or "path/to/robot.urdf" (relative to ROOT or ERD)
    origin: str  # where it comes from, for the table


def _erd(relative: str) -> str:
    return f"erd:{relative}"


CORPUS: tuple[ZooRobot, ...] = (
    ZooRobot("pr2", "pr2", "built-in"),
    ZooRobot("hsrb", "hsrb", "built-in"),
    ZooRobot("boxy", "boxy", "built-in"),
    *(
        ZooRobot(p.stem, str(p.relative_to(ROOT)), "examples/robots")
        for p in sorted((ROOT / "examples" / "robots").glob("*.py"))
        if not p.name.startswith("_")
    ),
    ZooRobot("stretch", "tests/data/stretch/stretch.py", "tests/data"),
    ZooRobot("fetch", "tests/data/fetch/fetch.py", "tests/data"),
    ZooRobot("erd_pr2", _erd("pr2_description/urdf/pr2.urdf"), "example-robot-data"),
    ZooRobot("tiago_dual", _erd("tiago_description/robots/tiago_dual.urdf"), "example-robot-data"),
    ZooRobot("alex", _erd("alex_description/urdf/alex_psyonic_hands.urdf"), "example-robot-data"),
    ZooRobot("centauro", _erd("centauro_description/urdf/centauro.urdf"), "example-robot-data"),
    ZooRobot("b1_z1", _erd("b1_description/urdf/b1-z1.urdf"), "example-robot-data"),
    ZooRobot(
        "anymal_kinova",
        _erd("anymal_b_simple_description/robots/anymal-kinova.urdf"),
        "example-robot-data",
    ),  # fmt: skip
    ZooRobot("ur5_gripper", _erd("ur_description/urdf/ur5_gripper.urdf"), "example-robot-data"),
    ZooRobot("ur3_gripper", _erd("ur_description/urdf/ur3_gripper.urdf"), "example-robot-data"),
    ZooRobot("kinova", _erd("kinova_description/robots/kinova.urdf"), "example-robot-data"),
    ZooRobot("xarm7", _erd("xarm_description/urdf/xarm7.urdf"), "example-robot-data"),
    ZooRobot("so100", _erd("so_arm_description/urdf/so100.urdf"), "example-robot-data"),
    *(
        ZooRobot(p.name, str((p / f"{p.name}.urdf").relative_to(ROOT)), "tests/data/zoo")
        for p in sorted((ROOT / "tests" / "data" / "zoo").iterdir())
        if (p / f"{p.name}.urdf").is_file()
    ),
)


@dataclass(frozen=True)
class ZooResult:
    """How far one robot got: the last step passed (None: not even the draft)."""

    name: str
    origin: str
    reached: str | None
    seconds: float
    reason: str  # empty when every step passed
    fixed: bool = False  # its base is fixed: the workcell stands in for the kitchen

    @property
    def steps(self) -> tuple[str, ...]:
        """The steps that apply to it."""
        return FIXED_STEPS if self.fixed else STEPS

    @property
    def complete(self) -> bool:
        """Whether it passed every step that applies to it."""
        return self.reached == self.steps[-1]

    @property
    def kitchen(self) -> bool:
        """Whether it completed the kitchen transport (only a mobile robot can)."""
        return not self.fixed and self.complete


def _one_line(text: str) -> str:
    flat = " ".join(text.split())
    return flat if len(flat) <= REASON_WIDTH else flat[: REASON_WIDTH - 3].rstrip() + "..."


def _urdf_path(source: str) -> Path:
    if source.startswith("erd:"):
        from robocram.robots import example_robot_data_folder

        return example_robot_data_folder() / source[4:]
    return ROOT / source


def _draft(robot: ZooRobot, out: Path) -> str:
    """The description to use: a built-in's name, a kept file, or a fresh draft's file."""
    from robocram.robots import draft_description

    if not robot.source.endswith(".urdf"):
        return robot.source if "/" not in robot.source else str(ROOT / robot.source)
    out.mkdir(parents=True, exist_ok=True)
    module = out / f"{robot.name}.py"
    module.write_text(draft_description(_urdf_path(robot.source)).source(module), "utf-8")
    return str(module)


def parked_in_kitchen(name: str, out: Path) -> KitchenScene:
    """The kitchen scene of the corpus robot ``name`` (drafted into ``out`` as the zoo does),
    every arm at its parking pose: where the probes start."""
    from robocram.scenes import kitchen_scene

    entry = next(r for r in CORPUS if r.name == name)
    scene = kitchen_scene(_draft(entry, out))
    desc = scene.world.robot(scene.robot).description
    for spec in desc.arms.values():
        scene.world.set_joint_states(scene.robot, dict(spec.parking))
    return scene


def _check(spec: str) -> str:
    """Empty if the check passes, else its first failure with the fix on one line."""
    from robocram.robot_check import check_robot, description_from

    card = check_robot(description_from(spec))
    if card.passed:
        return ""
    first = card.failures()[0]
    fix = f"; fix: {first.fix}" if first.fix else ""
    return f"check {first.name}: {first.detail}{fix}"


def _pick_up(spec: str) -> None:
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.scenes import tabletop_scene

    scene = tabletop_scene(spec)
    try:
        with simulated_robot(scene.world, scene.robot):
            pick_up(scene.look_target)
    finally:
        scene.world.close()


def _is_fixed(spec: str) -> bool:
    from robocram.robots import load_description

    return load_description(spec).drive == "fixed"


def _workcell(spec: str, reached: list[str], doing: list[str]) -> None:
    """The mug, then the bowl, to other spots of the table, the robot where it stands;
    ``doing`` gets each item's kind as its transport starts."""
    from robocram.designators import an
    from robocram.plans import perform
    from robocram.projection import simulated_robot
    from robocram.scenes import workcell_scene, workcell_spots

    scene = workcell_scene(spec)
    spots = workcell_spots(scene)
    try:
        with simulated_robot(scene.world, scene.robot):
            for kind, item in (("mug", "mug-1"), ("bowl", "bowl-1")):
                doing.append(kind)
                perform(an.action(type="transporting", object=kind, target=spots[item]))
        reached.append("workcell")
    finally:
        scene.world.close()


def _transport(spec: str, reached: list[str]) -> None:
    from robocram.designators import a, an
    from robocram.plans import perform
    from robocram.projection import simulated_robot
    from robocram.scenes import kitchen_scene

    scene = kitchen_scene(spec)
    try:
        with simulated_robot(scene.world, scene.robot):
            for kind, item in (("mug", "mug-1"), ("bowl", "bowl-1")):
                target = a.location(on=("kitchen", "table_top"), for_=item)
                perform(an.action(type="transporting", object=kind, target=target))
                reached.append(kind)
    finally:
        scene.world.close()


def run_robot(robot: ZooRobot, out: Path) -> ZooResult:
    """Every step on ``robot`` until one fails; the failure's type and text as the reason."""
    start = time.perf_counter()
    reached: list[str] = []
    reason = ""
    fixed = False
    doing: list[str] = []  # the workcell's item under way
    warnings.simplefilter("ignore")
    try:
        spec = _draft(robot, out)
        reached.append("draft")
        fixed = _is_fixed(spec)
        reason = _check(spec)
        if not reason:
            reached.append("check")
            _pick_up(spec)
            reached.append("pick-up")
            if fixed:
                _workcell(spec, reached, doing)
            else:
                _transport(spec, reached)
    except Exception as err:  # noqa: BLE001 - the zoo reports what stops a robot
        steps = FIXED_STEPS if fixed else STEPS
        step = steps[len(reached)] if len(reached) < len(steps) else "after"
        step = f"{step}: {doing[-1]}" if step == "workcell" and doing else step
        reason = f"{step}: {type(err).__name__}: {err}"
        if "--trace" in sys.argv:
            traceback.print_exc()
    last = reached[-1] if reached else None
    seconds = time.perf_counter() - start
    return ZooResult(robot.name, robot.origin, last, seconds, _one_line(reason), fixed)


def _worker(robot: ZooRobot, out: Path, queue: multiprocessing.Queue[ZooResult]) -> None:
    queue.put(run_robot(robot, out))


def run_isolated(robot: ZooRobot, out: Path, timeout: float) -> ZooResult:
    """:func:`run_robot` in a process of its own, stopped after ``timeout`` [s]."""
    context = multiprocessing.get_context("spawn")
    queue: multiprocessing.Queue[ZooResult] = context.Queue()
    start = time.perf_counter()
    process = context.Process(target=_worker, args=(robot, out, queue))
    process.start()
    process.join(timeout)
    if process.is_alive():
        process.terminate()
        process.join()
        seconds = time.perf_counter() - start
        why = f"timed out after {timeout:.0f} s"
        return ZooResult(robot.name, robot.origin, None, seconds, why)
    if queue.empty():
        code = process.exitcode
        return ZooResult(robot.name, robot.origin, None, 0.0, f"its process died (exit {code})")
    return queue.get()


def table(results: list[ZooResult]) -> str:
    """The results as a Markdown table, with the share that completed every step."""
    lines = [
        "| robot | from | step reached | time [s] | where it stopped |",
        "|---|---|---|---|---|",
    ]
    for r in results:
        reached = "all" if r.complete else (r.reached or "none")
        lines.append(f"| {r.name} | {r.origin} | {reached} | {r.seconds:.0f} | {r.reason} |")
    total = max(1, len(results))
    kitchen = sum(r.kitchen for r in results)
    done = sum(r.complete for r in results)
    fixed = [r for r in results if r.fixed]
    lines.append(
        f"\nWith the kitchen: {kitchen} of {len(results)} robots ({100.0 * kitchen / total:.0f} %)"
        f" completed every step ({len(results) - len(fixed)} are mobile)."
    )
    lines.append(
        f"With every step that applies: {done} of {len(results)} robots ({100.0 * done / total:.0f}"
        f" %) completed every step (the workcell, not the kitchen, for the {len(fixed)} whose"
        f" base is fixed: {sum(r.complete for r in fixed)} of them completed it)."
    )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    """Run the corpus (or ``--only`` some of it) and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", nargs="*", default=None, help="robot names to run")
    parser.add_argument("--timeout", type=float, default=900.0, help="[s] per robot")
    parser.add_argument("--out", type=Path, default=ROOT / "out" / "zoo", help="drafts go here")
    parser.add_argument("--trace", action="store_true", help="print each failure's traceback")
    args = parser.parse_args(argv)
    robots = [r for r in CORPUS if args.only is None or r.name in args.only]
    results = []
    for robot in robots:
        result = run_isolated(robot, args.out, args.timeout)
        results.append(result)
        reached = "all" if result.complete else result.reached
        print(f"{robot.name}: {reached} in {result.seconds:.0f} s {result.reason}", flush=True)
    print()
    print(table(results))


if __name__ == "__main__":
    main()

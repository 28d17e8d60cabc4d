"""Time sequential motion PERFORMs end to end: ground, match, serialise, execute.

Two process modules: a trivial one (the cost of PERFORM itself) and the turtle's
navigation driving tiny steps (``driving`` with one simulated step per command).
"""

from __future__ import annotations

import argparse
import time
from typing import Any

from robocram.designators import a
from robocram.execution.environment import Environment
from robocram.execution.perform import perform
from robocram.execution.process_module import ProcessModule
from robocram.execution.top_level import run_top_level
from robocram.turtlesim import TurtleWorld, turtle_environment

TRIVIAL_FACTS = """
motion_grounding(D, nop(N)) :- desig_prop(D, type, nothing), desig_prop(D, n, N).
matching_process_module(D, nop) :- desig_prop(D, type, nothing).
available_process_module(nop).
"""


class NopPM(ProcessModule):
    """Returns its argument: measures PERFORM, not the robot."""

    name = "nop"

    def execute(self, command: Any) -> Any:
        return command.args[0]


def run(label: str, env: Environment, make: Any, count: int) -> None:
    """Perform ``count`` motions made by ``make(i)`` in ``env`` and print the figures."""

    def plan() -> None:
        for i in range(count):
            perform(make(i))

    with env:
        started = time.perf_counter()
        run_top_level(plan)
        total = time.perf_counter() - started
    print(f"{label:<28} {count:>6} performs  {total:8.3f} s  {total / count * 1e6:9.1f} us/perform")


def main() -> None:
    """Parse the size and run both benchmarks."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--count", type=int, default=1000)
    count = parser.parse_args().count
    run(
        "trivial process module",
        Environment("nop", [NopPM()], TRIVIAL_FACTS),
        lambda i: a.motion(type="nothing", n=i),
        count,
    )
    world = TurtleWorld(time_step=1.0)  # one simulated step per 1 s drive command
    run(
        "turtle driving (1 step)",
        turtle_environment(world),
        lambda i: a.motion(type="driving", speed=0.001, angle=0.01),
        count,
    )


if __name__ == "__main__":
    main()

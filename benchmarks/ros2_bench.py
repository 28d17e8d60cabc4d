"""ROS 2 figures next to ROS 1's, in the same run (issue 36's goals).

For each ROS: the time to enter ``ros_robot`` (our node started and the robot's first
state in), the plan-side overhead per goal (from the call to the goal handed to ROS by
our node, plus from our node getting the result to the outcome checked), the time from a
stopped navigation task to the cancel seen by the driver, and a kitchen transport of the
mug (the real PR2's controllers) against the same transport in projection (measured
once, after a warm-up run, and compared with both). ROS 1 runs
against a roscore on a free port, ROS 2 on a domain of its own; the driver is our
projection driver in another process in both. Usage:
``python benchmarks/ros2_bench.py [runs]``. Goals: <= 2 s, <= 5 ms, <= 50 ms, <= 2x.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import ros_bench  # noqa: E402 - the ROS 1 figures, measured the same way

from robocram.projection import simulated_robot  # noqa: E402
from robocram.ros import Roscore, ros_robot  # noqa: E402
from robocram.ros.ros2_domain import free_domain  # noqa: E402
from robocram.ros_driver.driver_process import DriverProcess  # noqa: E402
from robocram.scenes import kitchen_scene  # noqa: E402

KITCHEN_RUNS = 2  # a transport takes seconds, and each needs a fresh driver


def entering2(domain: int, runs: int) -> float:
    """Median [s] to enter ``ros_robot(ros=2)``: node up, the robot's first state in."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        with ros_robot("pr2", ros=2, domain_id=domain):
            times.append(time.perf_counter() - t0)
    return statistics.median(times)


def stop_to_cancel2_ms(domain: int, runs: int) -> float:
    """Median [ms] from a stopped navigation task to the cancel seen by the ROS 2 driver."""
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "goals.jsonl"
        with (
            DriverProcess(
                "", "pr2", base_speed=0.2, goal_log=log, ros=2, domain_id=domain
            ) as driver,
            ros_robot("pr2", ros=2, domain_id=domain),
        ):
            stops = [ros_bench._going_stopped_after(0.3, -1.0 - 0.1 * (i % 2)) for i in range(runs)]
            seen = driver.cancels_seen("/navigate_to_pose")
    return 1e3 * statistics.median(c - s for s, c in zip(stops, seen, strict=True))


def projected_mug(runs: int) -> float:
    """Median [s] of the mug's kitchen transport in projection, after one to warm up the
    plan side's caches (IK, grasps), which the ROS runs after it then find warm too."""
    times = []
    for _ in range(runs + 1):
        scene = kitchen_scene("pr2")
        with simulated_robot(scene.world, "pr2"):
            times.append(ros_bench._to_the_table("mug"))
        scene.world.close()
    return statistics.median(times[1:])


def mug_over_ros(runs: int, ros: int, where: str | int) -> float:
    """Median [s] of the mug's kitchen transport over ROS ``ros`` (the real PR2's
    controllers), each on a fresh kitchen and driver."""
    times = []
    for _ in range(runs):
        scene = kitchen_scene("pr2")
        if ros == 1:
            driver = DriverProcess(str(where), controllers="pr2", scene="kitchen")
            block = ros_robot("pr2", str(where), world=scene.world)
        else:
            driver = DriverProcess(
                "", controllers="pr2", scene="kitchen", ros=2, domain_id=int(where)
            )
            block = ros_robot("pr2", ros=2, domain_id=int(where), world=scene.world)
        with driver, block:
            times.append(ros_bench._to_the_table("mug"))
        scene.world.close()
    return statistics.median(times)


def ros1_figures(runs: int) -> dict[str, float]:
    """ROS 1's figures: entering, overhead per goal, stop to cancel, the transport [s]."""
    with Roscore() as core:
        with DriverProcess(core.uri, "pr2"):
            enter = ros_bench.entering(core, runs)
            with ros_robot("pr2", core.uri) as run:
                overhead = ros_bench.goal_overhead_ms(run.environment.client, runs)
        cancel = ros_bench.stop_to_cancel_ms(core, runs)
        transport = mug_over_ros(min(runs, KITCHEN_RUNS), 1, core.uri)
    return _figures(enter, overhead, cancel, transport)


def ros2_figures(runs: int) -> dict[str, float]:
    """ROS 2's figures, as ROS 1's, on a domain of their own."""
    with free_domain() as domain:
        with DriverProcess("", "pr2", ros=2, domain_id=domain):
            enter = entering2(domain, runs)
            with ros_robot("pr2", ros=2, domain_id=domain) as run:
                overhead = ros_bench.goal_overhead_ms(run.environment.client, runs)
        cancel = stop_to_cancel2_ms(domain, runs)
        transport = mug_over_ros(min(runs, KITCHEN_RUNS), 2, domain)
    return _figures(enter, overhead, cancel, transport)


def _figures(enter: float, overhead: float, cancel: float, transport: float) -> dict[str, float]:
    return {
        "enter ros_robot [s]": enter,
        "plan overhead per goal [ms]": overhead,
        "stop to cancel seen [ms]": cancel,
        "mug transport [s]": transport,
    }


GOALS = {
    "enter ros_robot [s]": "<= 2",
    "plan overhead per goal [ms]": "<= 5",
    "stop to cancel seen [ms]": "<= 50",
    "  over ROS / projection": "<= 2",
}


def main(runs: int) -> None:
    """Print ROS 1's and ROS 2's figures side by side, with the issue's goals."""
    projected = projected_mug(min(runs, KITCHEN_RUNS))
    one = ros1_figures(runs)
    two = ros2_figures(runs)
    for figures in (one, two):
        figures["  over ROS / projection"] = figures["mug transport [s]"] / projected
    print(f"PR2, median of {runs} (transports: of {min(runs, KITCHEN_RUNS)})")
    print(f"{'figure':32} {'ROS 1':>9} {'ROS 2':>9}   goal")
    for name, value in one.items():
        print(f"{name:32} {value:9.3f} {two[name]:9.3f}   {GOALS.get(name, '')}")
    print(f"{'mug transport in projection [s]':32} {projected:9.3f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)

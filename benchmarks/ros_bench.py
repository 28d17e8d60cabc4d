"""ROS figures: PERFORM per motion type over ROS 1 against direct projection, and the
latency of one round trip (our node's pipe, a goal and the state after it, a PERFORM).

A real roscore on a free port and our projection driver (motions as jumps, like
projection) serve the PR2 of the tabletop scene; the same motions run in projection in
the same scene. Prints medians [ms] over ``runs`` repetitions; CRAM's ROS process
modules (the reference) are not installable here. Then the kitchen transports (the mug
from the counter, the bowl from a drawer) on the driver's kitchen with the real PR2's
controllers against projection, median of at most ``KITCHEN_RUNS`` (each run needs a
fresh kitchen on both sides). Usage: ``python benchmarks/ros_bench.py [runs]``.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from robocram.designators import a, an
from robocram.execution import perform, pursue, sleep
from robocram.execution.failures import TorsoGoalNotReached
from robocram.logic import current_kb
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.ros import Roscore, RosMasterUnreachable, ros_robot
from robocram.ros.goal_runner import checked
from robocram.ros.ros_robot_client import RosRobotClient
from robocram.ros.roscore import free_port
from robocram.ros.transport import GoalHandle, GoalOutcome
from robocram.ros_driver.driver_process import DriverProcess
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.tf import Pose, PoseStamped

DOWN = (0.0, 0.7071068, 0.0, 0.7071068)  # the PR2's tool pointing down
PARKED = {"r_shoulder_lift_joint": 0.3, "r_elbow_flex_joint": -1.0}
UNPARKED = {"r_shoulder_lift_joint": 0.1, "r_elbow_flex_joint": -0.6}
KITCHEN_RUNS = 3  # a transport takes seconds, and each needs a fresh driver
ITEMS = {"mug": "mug-1", "bowl": "bowl-1"}


def motions(look: PoseStamped) -> dict[str, Callable[[int], object]]:
    """One PERFORM per motion type; ``i`` alternates goals so every call moves."""

    def tcp(i: int) -> PoseStamped:
        return PoseStamped("base_footprint", (0.55, -0.2, 0.85 + 0.05 * (i % 2)), DOWN)

    return {
        "going": lambda i: perform(
            a.motion(type="going", target=a.location(pose=Pose((-0.1 * (i % 2), 0.0, 0.0))))
        ),
        "moving-torso": lambda i: perform(
            a.motion(type="moving-torso", joint_angle=0.1 + 0.1 * (i % 2))
        ),
        "looking": lambda i: perform(a.motion(type="looking", target=a.location(pose=look))),
        "detecting": lambda i: perform(a.motion(type="detecting", object=an.object(type="mug"))),
        "opening/closing": lambda i: perform(
            a.motion(type=("opening", "closing")[i % 2], gripper="left")
        ),
        "moving-arm-joints": lambda i: perform(
            a.motion(
                type="moving-arm-joints",
                arm="right",
                configuration=(PARKED, UNPARKED)[i % 2],
            )
        ),
        "moving-tcp": lambda i: perform(
            a.motion(type="moving-tcp", arm="right", target=a.location(pose=tcp(i)))
        ),
    }


def park_and_look(look: PoseStamped) -> None:
    """Park both arms (out of the camera's view) and look at the table."""
    for side in ("left", "right"):
        parking = current_kb().first("robot_arms_parking_joint_states(pr2, A, S)", A=side)
        assert parking is not None  # the PR2 has parking states
        perform(a.motion(type="moving-arm-joints", arm=side, configuration=parking["S"]))
    perform(a.motion(type="looking", target=a.location(pose=look)))


def _median_ms(step: Callable[[int], object], runs: int) -> float:
    times = []
    step(runs)  # warm up (IK caches, connections)
    for i in range(runs):
        t0 = time.perf_counter()
        step(i)
        times.append(time.perf_counter() - t0)
    return 1e3 * statistics.median(times)


def direct(runs: int) -> dict[str, float]:
    """Median [ms] per motion type in projection."""
    scene = tabletop_scene("pr2")
    with simulated_robot(scene.world, "pr2"):
        park_and_look(scene.look_target)
        return {name: _median_ms(step, runs) for name, step in motions(scene.look_target).items()}


def over_ros(core: Roscore, runs: int) -> tuple[dict[str, float], dict[str, float]]:
    """Median [ms] per motion type over ROS, and the round-trip latencies."""
    look = tabletop_scene("pr2").look_target
    with DriverProcess(core.uri, "pr2"), ros_robot("pr2", core.uri) as run:
        park_and_look(look)
        per_motion = {name: _median_ms(step, runs) for name, step in motions(look).items()}
        client = run.environment.client
        transport = client.transport
        torso = {"trajectory": {"joint_names": ["torso_lift_joint"], "points": [
            {"positions": [0.1], "time_from_start": {"secs": 0, "nsecs": 0}}]}}  # fmt: skip

        def goal(_: int) -> object:
            return client.run("torso", torso, TorsoGoalNotReached)

        latency = {
            "pipe request to our node": _median_ms(lambda _: transport.joint_states(), runs),
            "goal + state after it": _median_ms(goal, runs),
            "PERFORM torso, no motion": _median_ms(
                lambda _: perform(a.motion(type="moving-torso", joint_angle=0.1)), runs
            ),
        }
    return per_motion, latency


def entering(core: Roscore, runs: int) -> float:
    """Median [s] to enter ``ros_robot`` (our node joined, the block running)."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        with ros_robot("pr2", core.uri):
            times.append(time.perf_counter() - t0)
    return statistics.median(times)


def no_master() -> float:
    """[s] until entering with no master raises RosMasterUnreachable (default timeout)."""
    t0 = time.perf_counter()
    try:
        with ros_robot("pr2", f"http://127.0.0.1:{free_port()}"):
            pass
    except RosMasterUnreachable:
        return time.perf_counter() - t0
    raise AssertionError("a ROS master answered where none should run")


def _outcome(handle: GoalHandle) -> GoalOutcome:
    with handle.done:
        handle.done.wait_for(lambda: handle.outcome is not None)
    assert handle.outcome is not None
    return handle.outcome


def goal_overhead_ms(client: RosRobotClient, runs: int) -> float:
    """Median [ms] the plan side adds per goal: from the call to the goal handed to ROS by
    our node, plus from our node getting the result to the outcome checked."""
    interface = client.config.action("torso")
    transport = client.transport
    torso = {"trajectory": {"joint_names": ["torso_lift_joint"], "points": [
        {"positions": [0.1], "time_from_start": {"secs": 0, "nsecs": 0}}]}}  # fmt: skip
    overheads = []
    for _ in range(runs + 1):
        t0 = time.monotonic()
        handle = transport.send_goal(interface.server, torso)
        outcome = checked(interface, _outcome(handle), TorsoGoalNotReached)
        t1 = time.monotonic()
        overheads.append((handle.sent - t0) + (t1 - outcome.arrived))
    return 1e3 * statistics.median(overheads[1:])  # the first warms up


def _going_stopped_after(seconds: float, x: float) -> float:
    """Start going to ``(x, 0)`` and stop it after ``seconds``; when it was stopped."""
    stopped: list[float] = []

    def stop_soon() -> None:
        sleep(seconds)
        stopped.append(time.monotonic())

    pursue(
        lambda: perform(a.motion(type="going", target=a.location(pose=Pose((x, 0.0, 0.0))))),
        stop_soon,
    )
    return stopped[0]


def stop_to_cancel_ms(core: Roscore, runs: int) -> float:
    """Median [ms] from a stopped navigation task to the cancel seen by the driver."""
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "goals.jsonl"
        with (
            DriverProcess(core.uri, "pr2", base_speed=0.2, goal_log=log) as driver,
            ros_robot("pr2", core.uri),
        ):
            stops = [_going_stopped_after(0.3, -1.0 - 0.1 * (i % 2)) for i in range(runs)]
            seen = driver.cancels_seen("/move_base")
    return 1e3 * statistics.median(c - s for s, c in zip(stops, seen, strict=True))


def _to_the_table(object_type: str) -> float:
    """[s] one transport of ``object_type`` to the kitchen's table top, in the block."""
    target = a.location(on=("kitchen", "table_top"), for_=ITEMS[object_type])
    t0 = time.perf_counter()
    transport(object_type, target)
    return time.perf_counter() - t0


def kitchen(core: Roscore, runs: int) -> dict[str, tuple[float, float]]:
    """Median [s] of each kitchen transport in projection and over ROS (real PR2 mode)."""
    figures = {}
    for object_type in ITEMS:
        projected, ros = [], []
        for _ in range(min(runs, KITCHEN_RUNS)):
            scene = kitchen_scene("pr2")
            with simulated_robot(scene.world, "pr2"):
                projected.append(_to_the_table(object_type))
            scene.world.close()
            scene = kitchen_scene("pr2")
            with (
                DriverProcess(core.uri, controllers="pr2", scene="kitchen"),
                ros_robot("pr2", core.uri, world=scene.world),
            ):
                ros.append(_to_the_table(object_type))
            scene.world.close()
        figures[object_type] = (statistics.median(projected), statistics.median(ros))
    return figures


def main(runs: int) -> None:
    """Print the per-motion table, the round-trip latencies and the ROS-semantics figures."""
    projected = direct(runs)
    with Roscore() as core:
        ros, latency = over_ros(core, runs)
        with DriverProcess(core.uri, "pr2"):
            enter = entering(core, runs)
            with ros_robot("pr2", core.uri) as run:
                overhead = goal_overhead_ms(run.environment.client, runs)
        cancel = stop_to_cancel_ms(core, runs)
        transports = kitchen(core, runs)
    absent = no_master()
    print(f"PR2, median of {runs} PERFORMs [ms]")
    print(f"{'motion':20} {'projection':>11} {'ROS':>9} {'overhead':>9}")
    for name, value in projected.items():
        print(f"{name:20} {value:11.2f} {ros[name]:9.2f} {ros[name] - value:9.2f}")
    print("round trips [ms]")
    for name, value in latency.items():
        print(f"  {name:32} {value:7.2f}")
    print("ROS semantics (median)          value    goal")
    print(f"  enter ros_robot [s]          {enter:8.3f}   <= 2")
    print(f"  no master, typed error [s]   {absent:8.3f}   <= 5")
    print(f"  plan overhead per goal [ms]  {overhead:8.3f}   <= 5")
    print(f"  stop to cancel seen [ms]     {cancel:8.3f}   <= 50")
    print(f"kitchen transport to the table [s], median of {min(runs, KITCHEN_RUNS)}")
    print(f"{'object':20} {'projection':>11} {'ROS':>9}")
    for name, (value, over) in transports.items():
        print(f"{name:20} {value:11.2f} {over:9.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)

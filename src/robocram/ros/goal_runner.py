"""Run one action goal with ROS semantics: time budget, cancel on stop, typed failures.

The caller's task waits for the outcome at a stop point. If the task is stopped (a
``pursue`` sibling won, the top level was stopped) the goal is cancelled and the wait
goes on until the server confirms, so the robot has stopped when the stop unwinds. A goal
over its time budget is cancelled and fails with ``ActionlibActionTimedOut`` naming the
server; ABORTED and REJECTED raise the resource's failure with the server's status text;
a lost connection raises ``RosConnectionLost``.
"""

from __future__ import annotations

from collections.abc import Callable

from robocram.execution.failures import ActionlibActionTimedOut, PlanFailure
from robocram.execution.task import TaskStopped
from robocram.execution.task_context import wait_until
from robocram.ros.errors import RosConnectionLost
from robocram.ros.ros_config import ActionInterface
from robocram.ros.transport import GoalHandle, GoalOutcome, GoalState, RosDict, Transport

CANCEL_TIMEOUT = 5.0  # [s] to wait for the server to confirm a cancel
FailureFactory = Callable[[str], PlanFailure]
Settle = Callable[[GoalOutcome], None]


def _wait(handle: GoalHandle, timeout: float | None) -> bool:
    return wait_until(handle.done, lambda: handle.outcome is not None, timeout)


def _cancel_and_wait(transport: Transport, handle: GoalHandle, settle: Settle) -> None:
    """Cancel, wait for the server's confirmation, then for the state after it."""
    transport.cancel_goal(handle)
    with handle.done:
        handle.done.wait_for(lambda: handle.outcome is not None, CANCEL_TIMEOUT)
    if handle.outcome is not None and handle.outcome.state is not GoalState.LOST:
        settle(handle.outcome)


def _no_settling(_: GoalOutcome) -> None:
    """Goals whose caller reads no state afterwards need not wait for it."""


def run_goal(
    transport: Transport,
    interface: ActionInterface,
    goal: RosDict,
    failure: FailureFactory,
) -> GoalOutcome:
    """Send ``goal`` to ``interface``'s server and return its SUCCEEDED outcome.

    Args:
        failure: builds the resource's typed failure from a message (ABORTED, REJECTED).

    Raises:
        ActionlibActionTimedOut: the goal ran past ``interface.timeout`` (it is cancelled).
        RosConnectionLost: the server or our ROS node went away.
        TaskStopped: the task was stopped; the goal was cancelled first.
    """
    return checked(interface, finish_goal(transport, interface, goal, _no_settling), failure)


def finish_goal(
    transport: Transport, interface: ActionInterface, goal: RosDict, settle: Settle
) -> GoalOutcome:
    """Send ``goal``; return how it ended, after ``settle`` (timeouts raise, see run_goal).

    ``settle(outcome)`` runs once the goal has ended, also when it was cancelled, unless
    the connection was lost: the process module waits there for the state after it.
    """
    handle = transport.send_goal(interface.server, goal)
    try:
        finished = _wait(handle, interface.timeout)
    except TaskStopped:
        _cancel_and_wait(transport, handle, settle)
        raise
    if not finished:
        _cancel_and_wait(transport, handle, settle)
        raise ActionlibActionTimedOut(
            f"the goal to {interface.server} ({interface.resource}) did not finish within "
            f"{interface.timeout} s; it was cancelled",
            action=interface.server,
            timeout=interface.timeout,
        )
    outcome = handle.outcome
    assert outcome is not None  # _wait returned True
    if outcome.state is not GoalState.LOST:
        settle(outcome)
    return outcome


def checked(
    interface: ActionInterface, outcome: GoalOutcome, failure: FailureFactory
) -> GoalOutcome:
    """``outcome`` if it SUCCEEDED, else the typed failure it stands for (raised)."""
    state = outcome.state
    if state is GoalState.SUCCEEDED:
        return outcome
    server = interface.server
    if state is GoalState.LOST:
        raise RosConnectionLost(
            f"lost {server} mid-goal: {outcome.status_text}",
            server=server,
            reason=outcome.status_text,
        )
    text = outcome.status_text or "no status text"
    error = failure(f"{server} {state.name}: {text}")
    raise error.add_context(controller=server, status=state.name, status_text=outcome.status_text)

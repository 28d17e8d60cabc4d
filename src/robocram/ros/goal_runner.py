"""Run one action goal with ROS semantics: time budget, cancel on stop, typed failures.

The caller's task waits for the outcome at a stop point. If the task is stopped (a
``pursue`` sibling won, the top level was stopped) the goal is cancelled and the wait
goes on until the server confirms, so the robot has stopped when the stop unwinds. A goal
over its time budget is cancelled and fails with ``ActionlibActionTimedOut`` naming the
server; ABORTED and REJECTED raise the resource's failure with the controller's own words
(status text, ``error_code`` and ``error_string``); a lost connection raises
``RosConnectionLost``; a cancel the server does not confirm within the interface's
``cancel_timeout`` raises ``RosCancelIgnored`` (the robot may still be moving).
"""

from __future__ import annotations

from collections.abc import Callable

from robocram.execution.failures import ActionlibActionTimedOut, PlanFailure
from robocram.execution.task import TaskStopped
from robocram.execution.task_context import wait_until
from robocram.ros.errors import RosCancelIgnored, RosConnectionLost
from robocram.ros.ros_config import ActionInterface
from robocram.ros.transport import GoalHandle, GoalOutcome, GoalState, RosDict, Transport

FailureFactory = Callable[[str], PlanFailure]
Settle = Callable[[GoalOutcome], None]
Accept = Callable[[GoalOutcome], bool]
# control_msgs/FollowJointTrajectoryResult error codes, named in failures
ERROR_CODES = {
    0: "SUCCESSFUL",
    -1: "INVALID_GOAL",
    -2: "INVALID_JOINTS",
    -3: "OLD_HEADER_TIMESTAMP",
    -4: "PATH_TOLERANCE_VIOLATED",
    -5: "GOAL_TOLERANCE_VIOLATED",
}
# nav2_msgs (Jazzy) error codes NavigateToPose passes on from its planner (2xx, from
# ComputePathToPose) and controller (1xx, from FollowPath); its result says them with
# ``error_msg`` where control_msgs say ``error_string``
NAV2_ERROR_CODES = {
    100: "UNKNOWN", 101: "INVALID_CONTROLLER", 102: "TF_ERROR", 103: "INVALID_PATH",
    104: "PATIENCE_EXCEEDED", 105: "FAILED_TO_MAKE_PROGRESS", 106: "NO_VALID_CONTROL",
    107: "CONTROLLER_TIMED_OUT", 200: "UNKNOWN", 201: "INVALID_PLANNER", 202: "TF_ERROR",
    203: "START_OUTSIDE_MAP", 204: "GOAL_OUTSIDE_MAP", 205: "START_OCCUPIED",
    206: "GOAL_OCCUPIED", 207: "TIMEOUT", 208: "NO_VALID_PATH",
}  # fmt: skip


def _wait(handle: GoalHandle, timeout: float | None) -> bool:
    return wait_until(handle.done, lambda: handle.outcome is not None, timeout)


def _cancel_and_wait(
    transport: Transport,
    interface: ActionInterface,
    handle: GoalHandle,
    settle: Settle,
    stopping: bool,
) -> None:
    """Cancel, wait for the server's confirmation, then for the state after it.

    Raises:
        RosCancelIgnored: no confirmation within ``interface.cancel_timeout``.
    """
    transport.cancel_goal(handle)
    with handle.done:
        confirmed = handle.done.wait_for(
            lambda: handle.outcome is not None, interface.cancel_timeout
        )
    if not confirmed:
        raise RosCancelIgnored(
            f"{interface.server} ({interface.resource}) did not confirm a cancel within "
            f"{interface.cancel_timeout} s: the robot may still be moving",
            server=interface.server,
            timeout=interface.cancel_timeout,
            stopping=stopping,
        )
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
        RosCancelIgnored: a cancel (stop or timeout) was not confirmed by the server.
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
        _cancel_and_wait(transport, interface, handle, settle, stopping=True)
        raise
    if not finished:
        _cancel_and_wait(transport, interface, handle, settle, stopping=False)
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


def controller_words(outcome: GoalOutcome) -> str:
    """The status text, ``error_code`` (named) and ``error_string`` (Nav2: ``error_msg``)
    of an outcome, joined."""
    words = [outcome.status_text] if outcome.status_text else []
    code = outcome.result.get("error_code")
    names = NAV2_ERROR_CODES if "error_msg" in outcome.result else ERROR_CODES
    if isinstance(code, int) and code != 0:
        words.append(f"error_code {code} ({names.get(code, 'unknown code')})")
    detail = outcome.result.get("error_string", outcome.result.get("error_msg"))
    if detail and detail != outcome.status_text:
        words.append(str(detail))
    return "; ".join(words) or "no status text, error code or error string"


def checked(
    interface: ActionInterface,
    outcome: GoalOutcome,
    failure: FailureFactory,
    accept: Accept | None = None,
) -> GoalOutcome:
    """``outcome`` if it SUCCEEDED (or ``accept`` takes it), else the typed failure it
    stands for (raised), carrying the controller's own words in its message and context."""
    state = outcome.state
    if state is GoalState.SUCCEEDED or (
        state is not GoalState.LOST and accept is not None and accept(outcome)
    ):
        return outcome
    server = interface.server
    if state is GoalState.LOST:
        raise RosConnectionLost(
            f"lost {server} mid-goal: {outcome.status_text}",
            server=server,
            reason=outcome.status_text,
        )
    error = failure(f"{server} {state.name}: {controller_words(outcome)}")
    error.add_context(
        controller=server,
        status=state.name,
        status_text=outcome.status_text,
        error_code=outcome.result.get("error_code"),
        error_string=outcome.result.get("error_string", outcome.result.get("error_msg")),
    )
    if outcome.feedback:  # where the server last said it was (Nav2: distance remaining)
        error.add_context(feedback=outcome.feedback)
    raise error

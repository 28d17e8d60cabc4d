"""Failure handling: handlers per failure type that retry the body or give a value.

A handler is called as ``handler(failure, control)``. It handles the failure only by
``retry()`` (run the protected body again) or ``control.return_value(v)`` (the form's
value is ``v``); anything else, including falling off the end or returning a value,
lets the failure propagate. So a failure can never be swallowed by accident.
Stopping a task (TaskStopped) is not a failure and never reaches a handler.
"""

from __future__ import annotations

import contextvars
import functools
from collections.abc import Callable, Mapping
from typing import Any, NoReturn, TypeVar

from robocram.execution.errors import ExecutionArgumentError, ExecutionUsageError
from robocram.execution.failures import RetryOutsideHandler
from robocram.execution.task import TaskStopped

T = TypeVar("T")


class FailureControl:
    """What a handler can do with the failure it was given."""

    def __init__(self, failure: Exception, retries: int) -> None:
        self.failure = failure
        self.retries = retries  # retries this handler already asked for in this form

    def retry(self) -> NoReturn:
        """Run the protected body again."""
        raise _Retry(self)

    def return_value(self, value: object) -> NoReturn:
        """End the form with ``value`` instead of the failure."""
        raise _Return(self, value)


Handler = Callable[[Any, FailureControl], object]

_HANDLING: contextvars.ContextVar[FailureControl | None] = contextvars.ContextVar(
    "robocram_failure_control", default=None
)


class _HandlerExit(BaseException):
    """Carries a handler's decision to its form; BaseException so no `except` eats it."""

    def __init__(self, control: FailureControl) -> None:
        super().__init__()
        self.control = control


class _Retry(_HandlerExit):
    pass


class _Return(_HandlerExit):
    def __init__(self, control: FailureControl, value: object) -> None:
        super().__init__(control)
        self.value = value


def retry() -> NoReturn:
    """Inside a handler: run the protected body of the innermost handling form again."""
    control = _HANDLING.get()
    if control is None:
        raise RetryOutsideHandler()
    control.retry()


class RetryCounter:
    """A retry budget, like CRAM's retry counters: ``counter.retry()`` retries while it lasts.

    Create it outside the protected body so it survives retries; once spent,
    ``retry()`` returns and the handler falls through, so the failure propagates.
    """

    def __init__(self, retries: int) -> None:
        if retries < 0:
            raise ExecutionArgumentError(
                f"RetryCounter needs a non-negative number of retries, got {retries}"
            )
        self.remaining = retries

    def retry(self) -> None:
        """Retry the protected body if the budget allows; otherwise return."""
        if self.remaining > 0:
            self.remaining -= 1
            retry()


def with_failure_handling(body: Callable[[], T], handlers: Mapping[Any, Handler]) -> T:
    """Run ``body``; on a failure, call the first handler whose type matches (dict order)."""
    _check_handlers(handlers)
    retries = dict.fromkeys(handlers, 0)
    while True:
        token = _HANDLING.set(None)  # retry() in the body itself is a mistake
        try:
            return body()
        except Exception as failure:
            kind = next((k for k in handlers if isinstance(failure, k)), None)
            if kind is None:
                raise
            decision, value = _decide(handlers[kind], FailureControl(failure, retries[kind]))
            if decision == "return":
                return value
            if decision == "propagate":
                raise
            retries[kind] += 1
        finally:
            _HANDLING.reset(token)


def _decide(handler: Handler, control: FailureControl) -> tuple[str, Any]:
    """Run a handler; return ("retry", None), ("return", value) or ("propagate", None)."""
    token = _HANDLING.set(control)
    try:
        handler(control.failure, control)
    except _HandlerExit as decision:
        if decision.control is not control:
            raise
        if isinstance(decision, _Return):
            return "return", decision.value
        return "retry", None
    finally:
        _HANDLING.reset(token)
    return "propagate", None


def _check_handlers(handlers: Mapping[Any, Handler]) -> None:
    for kind, handler in handlers.items():
        if not (isinstance(kind, type) and issubclass(kind, BaseException)):
            raise ExecutionUsageError(f"handler key {kind!r} is not an exception type")
        if issubclass(TaskStopped, kind) or not issubclass(kind, Exception):
            raise ExecutionUsageError(
                f"cannot handle {kind.__name__}: stopping a task is not a failure; "
                f"use PlanFailure (or a subclass) as the key"
            )
        if not callable(handler):
            raise ExecutionUsageError(f"handler for {kind.__name__} is {handler!r}, not a callable")


def failure_handled(
    handlers: Mapping[Any, Handler],
) -> Callable[[Callable[..., T]], Callable[..., T]]:
    """Decorator form: each call of the function runs under ``with_failure_handling``."""

    def decorate(fn: Callable[..., T]) -> Callable[..., T]:
        @functools.wraps(fn)
        def wrapper(*args: object, **kwargs: object) -> T:
            return with_failure_handling(lambda: fn(*args, **kwargs), handlers)

        return wrapper

    return decorate

"""Process modules: the one owner of a robot resource (base, neck, gripper, voice...).

A process module has a fixed lifecycle driven by the framework: ``start()`` (calls the
optional ``initialise`` hook), any number of serialised ``call(command)``, ``stop()``
(calls the optional ``terminate`` hook). Subclasses implement only ``execute(command)``.

Callers are served one at a time in arrival order: a second caller waits, it is not
lost. A waiting caller whose task is stopped leaves the queue. The command runs in the
caller's thread, so ``checkpoint()`` inside ``execute`` stops it with the caller's task.
The contract: a command that runs longer than ~100 ms (a trajectory, a drawer opened in
steps, a simulation) calls ``checkpoint()`` between its steps, so stopping its task ends
it within one step, and leaves the resource in a consistent state on ``TaskStopped``.
Failures re-raise in the caller with the module and command named (plan failures keep
their type and gain context; set-up failures and other errors are wrapped in
``ProcessModuleFailure``, the cause kept as its ``error``).
"""

from __future__ import annotations

import threading
import time
from collections import deque
from collections.abc import Iterable
from typing import Any, ClassVar

from robocram.execution.errors import ExecutionStateError, ExecutionUsageError
from robocram.execution.failures import (
    PlanFailure,
    ProcessModuleFailure,
    ProcessModuleInputError,
    SetupFailure,
)
from robocram.execution.task_context import checkpoint, wait_until
from robocram.tf import PoseValueError


class ProcessModule:
    """Base of process modules: set ``name`` (its atom in Prolog facts), implement ``execute``."""

    name: ClassVar[str] = ""

    def __init__(self) -> None:
        if not self.name or not isinstance(self.name, str):
            raise ExecutionUsageError(
                f"{type(self).__name__} needs a class attribute name = '<atom>', the name "
                "matching_process_module/2 facts use for it"
            )
        self._cond = threading.Condition()
        self._waiting: deque[object] = deque()
        self._busy = False
        self._running = False
        self._executed = 0

    def __repr__(self) -> str:
        state = "running" if self.running else "stopped"
        return f"<{type(self).__name__} {self.name!r} {state}>"

    def execute(self, command: object) -> Any:
        """Run one referenced command (a ``robocram.logic.Term``) on the resource; the one hook."""
        raise NotImplementedError(f"{type(self).__name__} must implement execute(command)")

    def initialise(self) -> None:
        """Hook run by ``start()`` before the module accepts commands."""

    def terminate(self) -> None:
        """Hook run by ``stop()`` after the last command finished."""

    @property
    def running(self) -> bool:
        """Whether the module accepts commands."""
        with self._cond:
            return self._running

    @property
    def busy(self) -> bool:
        """Whether a command is executing right now."""
        with self._cond:
            return self._busy

    @property
    def waiting(self) -> int:
        """How many callers wait for the module."""
        with self._cond:
            return len(self._waiting)

    @property
    def executed(self) -> int:
        """How many commands the module finished executing (successfully or not)."""
        with self._cond:
            return self._executed

    def start(self) -> None:
        """Start accepting commands (runs ``initialise``)."""
        with self._cond:
            if self._running:
                raise ExecutionStateError(f"process module {self.name!r} is already running")
        self.initialise()
        with self._cond:
            self._running = True

    def stop(self, timeout: float = 10.0) -> None:
        """Refuse new commands, release waiters, let the current one end (in ``timeout`` [s])."""
        with self._cond:
            self._running = False
            self._cond.notify_all()
            deadline = time.monotonic() + timeout
            while self._busy:
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    raise TimeoutError(
                        f"process module {self.name!r} still executes a command {timeout} s "
                        "after stop(); stop the task that performs it first"
                    )
                self._cond.wait(remaining)
        self.terminate()

    def call(self, command: object) -> Any:
        """Execute ``command`` once the module is free; callers are served in arrival order."""
        self._acquire(command)
        try:
            checkpoint()
            result = self._execute_named(command)
            checkpoint()
            return result
        finally:
            with self._cond:
                self._busy = False
                self._executed += 1
                self._cond.notify_all()

    def _acquire(self, command: object) -> None:
        ticket = object()
        with self._cond:
            self._require_running(command)
            self._waiting.append(ticket)
        try:
            wait_until(self._cond, lambda: self._free_for(ticket))
        except BaseException:
            with self._cond:
                self._waiting.remove(ticket)
                self._cond.notify_all()
            raise
        with self._cond:
            self._waiting.remove(ticket)
            if not self._running:
                self._cond.notify_all()
                self._require_running(command)
            self._busy = True

    def _free_for(self, ticket: object) -> bool:
        return not self._running or (not self._busy and self._waiting[0] is ticket)

    def _require_running(self, command: object) -> None:
        if not self._running:
            raise ProcessModuleFailure(
                f"process module {self.name!r} is not running, so it cannot execute {command}; "
                "perform inside process_modules_running(...) or an environment",
                module=self.name,
                command=command,
            )

    def _execute_named(self, command: object) -> Any:
        try:
            return self.execute(command)
        except (SetupFailure, PoseValueError) as err:  # the command is wrong: the caller's mistake
            raise ProcessModuleInputError(
                f"process module {self.name!r} refused {command}: {err}",
                module=self.name,
                command=command,
                error=err,
            ) from err
        except PlanFailure as failure:
            failure.add_context(process_module=self.name, command=command)
            raise
        except Exception as err:
            raise self._wrapped(command, err) from err

    def _wrapped(self, command: object, err: Exception) -> ProcessModuleFailure:
        return ProcessModuleFailure(
            f"process module {self.name!r} failed on {command}: {type(err).__name__}: {err}",
            module=self.name,
            command=command,
            error=err,
        )

    def unsupported(self, command: object, supported: Iterable[str]) -> ProcessModuleFailure:
        """Build the failure for a command this module does not handle (for ``execute``)."""
        return ProcessModuleFailure(
            f"process module {self.name!r} cannot execute {command}; it handles "
            f"{sorted(supported)}: check matching_process_module/2 for this module",
            module=self.name,
            command=command,
        )

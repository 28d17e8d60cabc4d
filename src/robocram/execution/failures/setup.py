"""Set-up failures: a plan or a module used where or how it cannot work.

A bad arm name, a plan started without a robot in its environment: the caller's bug, not
the world's. They are plan failures so one ``except PlanFailure`` sees everything a plan
can raise, but retrying does not help; a process module reports one raised in ``execute``
as a :class:`ProcessModuleFailure` naming the module, the command and this cause.
"""

from __future__ import annotations

from robocram.execution.failures.plan_failure import PlanFailure


class SetupFailure(PlanFailure):
    """A plan or a process module was set up or called wrongly (names the culprit and fix)."""

    summary = "the plan or a module was used wrongly"

"""Executive failures: designators and process modules, i.e. PERFORM's own failures."""

from __future__ import annotations

from robocram.execution.failures.plan_failure import PlanFailure


class DesignatorFailure(PlanFailure):
    """A designator could not be used."""

    fields = ("designator",)
    summary = "the designator could not be used"


class DesignatorReferenceFailure(DesignatorFailure):
    """A designator has no (further) solution."""

    summary = "the designator could not be referenced"
    hint = "check its properties against the grounding rules, or take another designator"


class DesignatorGoalParsingFailure(DesignatorFailure):
    """A designator's description cannot be read (a malformed key or value)."""

    summary = "the designator description could not be parsed"
    hint = "fix the description, e.g. a misspelled key"


class ProcessModuleFailure(PlanFailure):
    """A process module raised an error that is not a plan failure (wrapped, cause kept)."""

    fields = ("module", "command", "error")
    summary = "the process module failed"
    hint = "a wrapped Python error (the cause) is a bug in the module, not fixed by retrying"


class NoMatchingProcessModule(PlanFailure):
    """PERFORM found no running process module that handles the designator."""

    fields = ("designator", "running")
    summary = "no running process module matches the designator"
    hint = "start one with process_modules_running(...) or check matching_process_module/2"

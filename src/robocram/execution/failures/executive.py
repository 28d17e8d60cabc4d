"""Executive failures: designators and process modules, i.e. PERFORM's own failures."""

from __future__ import annotations

from robocram.designators import Designator
from robocram.execution.failures.plan_failure import PlanFailure


class DesignatorFailure(PlanFailure):
    """A designator could not be used."""

    designator: Designator | None = None
    summary = "the designator could not be used"


class DesignatorReferenceFailure(DesignatorFailure):
    """A designator has no (further) solution."""

    occluded_by: tuple[str, ...] | None = None  # a location: what hid its target
    blocked_by: tuple[str, ...] | None = None  # a location: what blocked its stands

    summary = "the designator could not be referenced"
    hint = "check its properties against the grounding rules, or take another designator"


class DesignatorGoalParsingFailure(DesignatorFailure):
    """A designator's description cannot be read (a malformed key or value)."""

    summary = "the designator description could not be parsed"
    hint = "fix the description, e.g. a misspelled key"


class ProcessModuleFailure(PlanFailure):
    """A process module raised an error that is not a plan failure (wrapped, cause kept)."""

    module: str | None = None
    command: object | None = None
    error: BaseException | None = None
    summary = "the process module failed"
    hint = "a wrapped Python error (the cause) is a bug in the module, not fixed by retrying"


class ProcessModuleInputError(ProcessModuleFailure):
    """A process module refused its command: a name or value in it is wrong (cause kept)."""

    summary = "the process module was given a command it cannot take"
    hint = (
        "the caller's mistake, not the module's: fix the name or value in the designator "
        "or plan that made the command"
    )


class NoMatchingProcessModule(PlanFailure):
    """PERFORM found no running process module that handles the designator."""

    designator: Designator | None = None
    running: list[str] | None = None
    summary = "no running process module matches the designator"
    hint = "start one with process_modules_running(...) or check matching_process_module/2"

"""A robot's report card: one line per check, what failed and the fix for it."""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robot_check.errors import CheckUnknownKey


@dataclass(frozen=True)
class CheckResult:
    """One check of one part: ``name`` (``"right arm: reach"``), passed, what was seen, fix."""

    name: str
    passed: bool
    detail: str
    fix: str = ""

    def line(self) -> str:
        """``ok   name: detail`` or ``FAIL name: detail; fix: ...``."""
        mark = "ok  " if self.passed else "FAIL"
        fix = f"\n       fix: {self.fix}" if self.fix and not self.passed else ""
        return f"{mark} {self.name}: {self.detail}{fix}"


@dataclass(frozen=True)
class ReportCard:
    """Every check made on one robot description, in the order they ran."""

    robot: str
    results: tuple[CheckResult, ...]

    @property
    def passed(self) -> bool:
        """Whether every check passed (and there was at least one)."""
        return bool(self.results) and all(r.passed for r in self.results)

    def failures(self) -> list[CheckResult]:
        """The checks that failed."""
        return [r for r in self.results if not r.passed]

    def result(self, name: str) -> CheckResult:
        """The check called ``name``; ``KeyError`` names the checks made."""
        for r in self.results:
            if r.name == name:
                return r
        raise CheckUnknownKey(
            f"no check {name!r} on {self.robot}; made: {[r.name for r in self.results]}"
        )

    def render(self) -> str:
        """The card as text: a title, one line per check, a summary."""
        failed = len(self.failures())
        summary = "all checks pass" if self.passed else f"{failed} of {len(self.results)} failed"
        lines = [f"report card of {self.robot}:", *(r.line() for r in self.results), summary]
        return "\n".join(lines)

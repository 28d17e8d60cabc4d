"""What fetch, deliver and transport tried: one entry per attempt, so bounds are checkable.

Plans retry a stage with the next solution of its location designator; each try is
recorded here with the stand it used and the failure it met (None when it worked), so a
caller or a test sees how many navigations a transport took and why each one failed.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from robocram.tf import Pose


@dataclass(frozen=True)
class Attempt:
    """One try of a stage (``fetch``, ``deliver``, ``open``, ``close``) at one stand."""

    stage: str
    stand: Pose | None  # [m] the base pose in map the try started from, if it got one
    failure: Exception | None  # None: the try worked

    @property
    def succeeded(self) -> bool:
        """Whether the try worked."""
        return self.failure is None


@dataclass
class AttemptLog:
    """Every attempt of a plan and its sub-plans, in order; containers it opened."""

    attempts: list[Attempt] = field(default_factory=list)
    opened: list[str] = field(default_factory=list)  # container links, in opening order

    def record(self, stage: str, stand: Pose | None, failure: Exception | None) -> None:
        """Add one attempt."""
        self.attempts.append(Attempt(stage, stand, failure))

    def of(self, stage: str) -> list[Attempt]:
        """The attempts of ``stage``, in order."""
        return [a for a in self.attempts if a.stage == stage]

    def failures(self, stage: str) -> list[Exception]:
        """The failures ``stage`` met, in order."""
        return [a.failure for a in self.of(stage) if a.failure is not None]

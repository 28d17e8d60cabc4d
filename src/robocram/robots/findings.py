"""What the checker finds beyond names: a fault (the description cannot work) or a warning.

A :class:`Finding` names its subject, the problem and the fix. Faults make
``load_description`` raise :class:`~robocram.robots.errors.DescriptionCheckError`;
warnings are logged, issued as :class:`DescriptionWarning` and kept in
``LoadedDescription.findings`` for a checker's report.
"""

from __future__ import annotations

import logging
import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Literal

LOG = logging.getLogger("robocram.robots")


class DescriptionWarning(UserWarning):
    """A description that loads but leaves out something plans need, or looks doubtful."""


@dataclass(frozen=True)
class Finding:
    """One problem of a description: what (``subject``), why it is wrong, how to fix it."""

    severity: Literal["fault", "warning"]
    subject: str  # the description field, e.g. "arms['right'].tool_frame"
    problem: str
    fix: str

    def message(self, model_name: str = "") -> str:
        """One line: subject, problem and fix."""
        return f"{self.subject}: {self.problem}; {self.fix}"


def warn(robot_name: str, findings: Iterable[Finding]) -> None:
    """Log and issue every warning among ``findings``."""
    for finding in findings:
        if finding.severity == "warning":
            text = f"robot {robot_name!r}: {finding.message()}"
            LOG.warning(text)
            warnings.warn(text, DescriptionWarning, stacklevel=3)

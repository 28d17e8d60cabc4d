"""Environment failures: articulated furniture (drawers, doors) and its surroundings."""

from __future__ import annotations

from robocram.execution.failures.high_level import HighLevelFailure


class EnvironmentUnreachable(HighLevelFailure):
    """The robot cannot get to the part of the environment it must manipulate."""

    environment_part: str | None = None
    summary = "the environment part is unreachable"
    hint = "try other base poses near the part"


class EnvironmentManipulationImpossible(HighLevelFailure):
    """Opening or closing the container failed."""

    environment_part: str | None = None
    action: str | None = None
    reached: float | None = None  # [m | rad] where the part was left (a roll moved it part way)
    summary = "the environment manipulation is impossible"
    hint = "check the handle and the joint of the container"

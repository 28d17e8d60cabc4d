"""The breakfast kitchen's batch plan: set the table for breakfast, then clear it again.

A batch plan is ``plan(look_target, **parameters)`` (see :mod:`robocram.batch.worker`);
the activities find the things themselves, so the look target is not used. The outcome
says where each thing was put and what was brought back (plain values that pickle).
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.batch.result import Pose7
from robocram.designators import an
from robocram.execution import perform
from robocram.plans.clearing_table import TableClearing
from robocram.plans.setting_table import TableSetting
from robocram.tf import PoseStamped


@dataclass(frozen=True)
class BreakfastOutcome:
    """Each thing put on the table and its spot (map), and the things brought back."""

    placed: tuple[tuple[str, Pose7], ...]
    returned: tuple[str, ...]


def breakfast(look_target: PoseStamped, people: int = 2, clear: bool = True) -> BreakfastOutcome:
    """Set the table for ``people``, then (``clear``) clear it again.

    Raises:
        ActivityIncomplete: a thing could not be brought (or brought back).
    """
    del look_target  # the activities look for the things themselves
    setting: TableSetting = perform(an.action(type="setting-table", people=people))
    placed = tuple(
        (name, (*spot.pose.position, *spot.pose.orientation))
        for name, spot in setting.placed.items()
    )
    if not clear:
        return BreakfastOutcome(placed, ())
    cleared: TableClearing = perform(an.action(type="clearing-table"))
    return BreakfastOutcome(placed, tuple(cleared.returned))

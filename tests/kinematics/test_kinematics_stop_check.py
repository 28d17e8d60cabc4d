"""solve_ik's stop hook: called once per descent, it may end the search but never steers it."""

from __future__ import annotations

import functools
import math

import pytest

from robocram.kinematics import IKOptions, solve_ik
from robocram.tf import Pose
from robocram.tf import quaternion as quat

HARD = Pose((0.45, -0.2, 0.75), quat.from_euler(0.0, math.pi / 2, 0.3))  # [m] in base_footprint


class Stop(Exception):
    """What the test's hook raises."""


def _always(values: dict[str, float]) -> bool:
    """A collision check that rejects every solution: the search runs its whole budget."""
    return True


def test_a_hook_that_never_stops_changes_nothing() -> None:
    for check in (None, _always):
        plain = solve_ik(
            "pr2", "right", HARD, options=IKOptions(random_seed=3), collision_check=check
        )
        calls: list[int] = []
        hooked = solve_ik(
            "pr2",
            "right",
            HARD,
            options=IKOptions(random_seed=3),
            collision_check=check,
            stop_check=functools.partial(calls.append, 1),
        )
        assert hooked.success == plain.success
        assert hooked.joint_positions == plain.joint_positions  # bit-identical
        assert hooked.iterations == plain.iterations
        assert len(calls) == plain.restarts + 1  # one call before every descent


def test_a_hook_that_raises_ends_the_search_at_that_descent() -> None:
    plain = solve_ik("pr2", "right", HARD, collision_check=_always)
    assert not plain.success and plain.restarts > 4
    calls: list[int] = []

    def stop_at_fifth() -> None:
        calls.append(1)
        if len(calls) == 5:
            raise Stop

    with pytest.raises(Stop):
        solve_ik("pr2", "right", HARD, collision_check=_always, stop_check=stop_at_fifth)
    assert len(calls) == 5

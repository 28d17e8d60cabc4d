"""A bad arm name in a motion is the caller's mistake, and the error says so (issue 11)."""

from __future__ import annotations

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ProcessModuleInputError
from robocram.projection import ProjectionError, simulated_robot
from robocram.world import World


def test_a_bad_arm_blames_the_caller_and_names_the_arms() -> None:
    with World() as world:
        world.add_robot("pr2")
        motion = a.motion(type="moving-arm-joints", arm="lft", configuration={})
        with simulated_robot(world, "pr2"), pytest.raises(ProcessModuleInputError) as info:
            perform(motion)
    text = str(info.value)
    assert isinstance(info.value.error, ProjectionError)
    assert "bug in the module" not in text
    assert "the caller's mistake" in text
    assert "its arms: 'left', 'right'" in text and "did you mean 'left'" in text

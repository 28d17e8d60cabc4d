"""``Versions.bodies``: the bodies' stamps read in one loop are each body's own stamp,
in order, and follow every write; an unknown body is named as before."""

from __future__ import annotations

import pytest

from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world.errors import UnknownObjectError


def test_a_flat_stamp_is_each_bodys_own_in_order() -> None:
    world = tabletop_scene("pr2").world
    versions = world.versions
    names = [o.name for o in world.objects()]
    handles = list(world.objects())

    def each() -> tuple[int, ...]:
        return tuple(t for name in names for t in versions.body(name))

    assert versions.bodies(names) == each() == versions.bodies(handles)
    assert versions.bodies([]) == ()
    before = versions.bodies(names)
    world.set_joint_states("pr2", {"torso_lift_joint": 0.2})
    world.set_pose("mug-1", Pose((1.0, 0.2, 0.9)))
    after = versions.bodies(names)
    assert after == each() and after != before
    changed = {names[k // 3] for k in range(len(after)) if after[k] != before[k]}
    assert changed == {"pr2", "mug-1"}
    with pytest.raises(UnknownObjectError, match="no-such-body"):
        versions.bodies([*names, "no-such-body"])
    world.close()

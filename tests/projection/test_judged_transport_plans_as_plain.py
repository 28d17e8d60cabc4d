"""A judged transport plans what a plain one does, to the bit.

The judge sets the world to every sample of each trajectory and puts it back through a
snapshot. PyBullet reads a base a last bit off what was written, so a snapshot that wrote
back what it read moved the robot by that bit, and the HSR's judged kitchen mug transport
took other stands than its plain run. Each trajectory, the joints, the robot's pose and
every object's pose when it is reported are compared bit for bit, read raw from PyBullet.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import ExitStack
from typing import Any

import numpy as np
import pybullet

from robocram.designators import a
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.world import World

TABLE = ("kitchen", "table_top")

Seen = tuple[str, tuple[str, ...], bytes, dict[str, tuple[float, ...]]]


def _raw(world: World) -> dict[str, tuple[float, ...]]:
    """Every body's base and joint positions, as PyBullet holds them."""
    cid = world.physics.client()
    state: dict[str, tuple[float, ...]] = {}
    for obj in world.objects():
        for body in obj.bodies:
            pos, orn = pybullet.getBasePositionAndOrientation(body, physicsClientId=cid)
            n = pybullet.getNumJoints(body, physicsClientId=cid)
            joints = (
                [s[0] for s in pybullet.getJointStates(body, range(n), physicsClientId=cid)]
                if n
                else []
            )
            state[f"{obj.name}/{body}"] = (*pos, *orn, *joints)
    return state


def _run(robot: str, judge: Callable[[World, str], Any] | None) -> list[Seen]:
    scene = kitchen_scene(robot)
    world = scene.world
    seen: list[Seen] = []

    def record(t: JointTrajectory) -> None:
        seen.append((t.kind, t.joint_names, np.asarray(t.positions()).tobytes(), _raw(world)))

    try:
        with ExitStack() as stack:
            stack.enter_context(trajectory_listener(record))
            if judge is not None:
                stack.enter_context(trajectory_listener(judge(world, scene.robot)))
            stack.enter_context(simulated_robot(world, scene.robot))
            transport("mug", a.location(on=TABLE, for_="mug-1"))
        seen.append(("end", (), b"", _raw(world)))
    finally:
        world.close()
    return seen


def test_the_hsr_judged_mug_transport_plans_as_its_plain_run(
    make_judge: Callable[..., Any],
) -> None:
    plain = _run("hsrb", None)
    judged = _run("hsrb", make_judge)
    assert len(plain) > 10
    assert [s[:2] for s in judged] == [s[:2] for s in plain]
    for i, (p, j) in enumerate(zip(plain, judged, strict=True)):
        assert j[2] == p[2], f"trajectory {i} ({p[0]}) differs"
        assert j[3] == p[3], f"the world differs when trajectory {i} ({p[0]}) is reported"

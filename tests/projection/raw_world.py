"""The raw world at each reported trajectory: every body's base and joint positions as
PyBullet holds them, with the trajectory's kind, joints and positions, to compare two runs
bit for bit (tests/projection/test_judged_transport_plans_as_plain.py)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pybullet

from robocram.motion import JointTrajectory
from robocram.world import World

Seen = tuple[str, tuple[str, ...], bytes, dict[str, tuple[float, ...]]]


def raw_state(world: World) -> dict[str, tuple[float, ...]]:
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


@dataclass
class RawRecord:
    """A trajectory listener keeping, per trajectory, what :data:`Seen` holds."""

    world: World
    seen: list[Seen] = field(default_factory=list)

    def __call__(self, trajectory: JointTrajectory) -> None:
        positions = np.asarray(trajectory.positions()).tobytes()
        self.seen.append(
            (trajectory.kind, trajectory.joint_names, positions, raw_state(self.world))
        )

    def end(self) -> None:
        """Keep the world as the run left it, as ``("end", (), b"", state)``."""
        self.seen.append(("end", (), b"", raw_state(self.world)))

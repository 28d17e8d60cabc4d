"""Switching off the default joint motors of joints that simulation holds anyway.

PyBullet gives every revolute and prismatic joint a velocity motor (target speed 0, at
most an impulse of 1 N s per step) that resists motion. A robot's held joints are put
back at their values after every step, so their motors change nothing the world keeps,
yet solving them costs a third of a kitchen step (~0.35 ms of 1.1 ms with a PR2). Joints
no longer held get their default motor back, so they stay as stiff as before.
"""

from __future__ import annotations

from collections.abc import Collection

from robocram.world.pybullet_backend import pybullet

DEFAULT_MOTOR_IMPULSE = 1.0  # [N s | N m s] per step: PyBullet's motor of a loaded joint


class HeldMotors:
    """Per body, the joints whose default motor is switched off (their held joints)."""

    def __init__(self) -> None:
        self._off: dict[int, frozenset[int]] = {}  # body id -> joint indices without motor

    def forget(self, body: int) -> None:
        """A body was created or removed: its joints have their default motors."""
        self._off.pop(body, None)

    def match(self, body: int, held: Collection[int], time_step: float, cid: int) -> None:
        """Motors off for ``held`` joints, default motors back for joints held before.

        ``time_step`` [s] turns the default impulse into the force PyBullet asks for.
        """
        off = self._off.get(body, frozenset())
        if off == held:
            return
        wanted = frozenset(held)
        stop = sorted(wanted - off)
        restore = sorted(off - wanted)
        if stop:
            _velocity_motors(body, stop, 0.0, cid)
        if restore:
            _velocity_motors(body, restore, DEFAULT_MOTOR_IMPULSE / time_step, cid)
        self._off[body] = wanted


def _velocity_motors(body: int, joints: list[int], force: float, cid: int) -> None:
    """Velocity motors (target 0) of at most ``force`` [N | N m] on ``joints``."""
    pybullet.setJointMotorControlArray(
        body,
        joints,
        pybullet.VELOCITY_CONTROL,
        targetVelocities=[0.0] * len(joints),
        forces=[force] * len(joints),
        physicsClientId=cid,
    )

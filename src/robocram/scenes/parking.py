"""Scenes start with the robot's arms parked, as every plan leaves them.

A drafted robot's zero pose may hang an arm in front of its own camera (the Fetch's does);
a scene that parks the arms first lets a plan that starts by looking (the README's torso
up, look, detect) run on any robot ``robocram robot check`` passes.
"""

from __future__ import annotations

from robocram.world import World


def park_arms(world: World, robot: str) -> dict[str, float]:
    """Put every arm of ``robot`` at its description's parking joints; return the values.

    A neck arm (Boxy's) is left where it is: it holds the camera, it is no arm to park.
    Loading a description checks its parking values against the joint limits, so they
    are applied as given.
    """
    desc = world.robot(robot).description
    arms = [arm for name, arm in desc.arms.items() if name != desc.neck_arm]
    parking = {j: v for arm in arms for j, v in arm.parking.items()}
    world.set_joint_states(robot, parking)
    return parking

"""An opening whose every stand the neck blocks looks ahead and opens from the stands again.

Boxy's household seed 13 (session 26): clearing came to the fridge with the neck still
turned to where it last looked (a cup on the table), and at each of the six opening stands
the base's goal was refused, the neck's links in the fridge; the milk stayed on the table.
Here Boxy's neck is wound as one of its looks left it (low to its right front), its links
then in the fridge at every stand (raw PyBullet, the base put at each), and the fridge
opens all the same: the door open (its joint, raw PyBullet), the robot touching nothing of
the kitchen.
"""

from __future__ import annotations

import pybullet

from robocram.plans.container_access import OPEN_RETRIES, open_from_front, opening_stands
from robocram.plans.containers import container
from robocram.plans.known_robot import current_robot
from robocram.plans.stands import yaw_of
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene

DOOR = "fridge_door_joint"
# [rad] Boxy's neck after a look at a point 1.14 m ahead of its base, 1.0 m to its right
# and 0.13 m over the floor (the look's IK depends on where the neck was before)
TURNED = {
    "neck_shoulder_pan_joint": 1.745,
    "neck_shoulder_lift_joint": 0.704,
    "neck_elbow_joint": -0.931,
    "neck_wrist_1_joint": 2.042,
    "neck_wrist_2_joint": -2.538,
    "neck_wrist_3_joint": -1.282,
}


def _link_indices(cid: int, body: int, names: set[str]) -> set[int]:
    return {
        j
        for j in range(pybullet.getNumJoints(body, physicsClientId=cid))
        if pybullet.getJointInfo(body, j, physicsClientId=cid)[12].decode() in names
    }


def _door(cid: int, kitchen: int) -> float:
    for j in range(pybullet.getNumJoints(kitchen, physicsClientId=cid)):
        if pybullet.getJointInfo(kitchen, j, physicsClientId=cid)[1].decode() == DOOR:
            return float(pybullet.getJointState(kitchen, j, physicsClientId=cid)[0])
    raise AssertionError(f"no {DOOR}")


def _neck_meets_kitchen_at(
    cid: int, robot: int, kitchen: int, neck: set[int], xy: tuple[float, float], yaw: float
) -> bool:
    """Whether a neck link touches the kitchen with the base put at ``xy``, ``yaw``."""
    here, q = pybullet.getBasePositionAndOrientation(robot, physicsClientId=cid)
    turn = pybullet.getQuaternionFromEuler((0.0, 0.0, yaw))
    pybullet.resetBasePositionAndOrientation(robot, (*xy, here[2]), turn, physicsClientId=cid)
    try:
        near = pybullet.getClosestPoints(robot, kitchen, 0.0, physicsClientId=cid)
        return any(point[3] in neck for point in near)
    finally:
        pybullet.resetBasePositionAndOrientation(robot, here, q, physicsClientId=cid)


def test_boxy_opens_the_fridge_with_its_neck_turned_into_every_stand() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    robot = world.object(scene.robot).body_id
    kitchen = world.object("kitchen").body_id
    try:
        with simulated_robot(world, scene.robot):
            known = current_robot()
            world.set_joint_states(scene.robot, TURNED)
            neck = _link_indices(cid, robot, set(known.neck_links()))
            part = container("fridge_body")
            stands = [s for _, s in zip(range(OPEN_RETRIES), opening_stands(part), strict=False)]
            blocked = [
                _neck_meets_kitchen_at(
                    cid, robot, kitchen, neck, s.pose.position[:2], yaw_of(s.pose)
                )
                for s in stands
            ]
            assert len(stands) == OPEN_RETRIES and all(blocked)  # every stand: the neck in it
            open_from_front("fridge_body")
            opening = part.opened
        assert _door(cid, kitchen) >= 0.8 * opening > 0.0
        assert not pybullet.getClosestPoints(robot, kitchen, 0.0, physicsClientId=cid)
    finally:
        world.close()

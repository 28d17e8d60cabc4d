"""Issue 37: a parked arm stays out of the body camera's view (Centauro, drafted as is).

Centauro's stowed left elbow hung before its head camera, and ``robot check`` could not
see the mug past it. The draft now stows such an arm again, out of the view. Judged with
raw PyBullet: rays from the camera across its field of view meet none of the arms' links.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pybullet
import pytest

from robocram.kinematics import forward_kinematics
from robocram.robots import example_robot_data_folder, load_description
from robocram.robots.description import RobotDescription
from tests.drafts import drafted

URDF = example_robot_data_folder() / "centauro_description" / "urdf" / "centauro.urdf"
RAYS = 9  # per side of the field of view
REACH = 1.5  # [m] rays this long: the table in front and the arms beside it


@pytest.fixture(scope="module")
def centauro() -> RobotDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return drafted(URDF).description


def test_the_parked_arms_leave_the_head_cameras_view_clear(centauro: RobotDescription) -> None:
    loaded = load_description(centauro)
    parked = {j: v for arm in loaded.arms.values() for j, v in arm.parking.items()}
    state = {**parked, **loaded.neck_parking}
    camera = loaded.cameras[0]
    eye = forward_kinematics(loaded, state, camera.frame).matrix()
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(loaded.urdf), useFixedBase=True, physicsClientId=client)
        names = {}
        for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
            info = pybullet.getJointInfo(body, i, physicsClientId=client)
            names[info[1].decode()] = i
            if info[1].decode() in state:
                pybullet.resetJointState(body, i, state[info[1].decode()], physicsClientId=client)
        links = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }
        arm_links = {
            links[name]
            for key, arm in loaded.arms.items()
            if key != loaded.neck_arm
            for name in (*arm.links, *arm.hand_links)
            if name in links
        }
        starts, ends = [], []
        for a in np.linspace(-camera.horizontal_fov / 2, camera.horizontal_fov / 2, RAYS):
            for b in np.linspace(-camera.vertical_fov / 2, camera.vertical_fov / 2, RAYS):
                direction = np.array((math.tan(a), math.tan(b), 1.0))
                direction /= np.linalg.norm(direction)
                starts.append(eye[:3, 3] + eye[:3, :3] @ (direction * 0.06))
                ends.append(eye[:3, 3] + eye[:3, :3] @ (direction * REACH))
        hits = pybullet.rayTestBatch(starts, ends, physicsClientId=client)
    finally:
        pybullet.disconnect(client)
    blocked = [h for h in hits if h[0] == body and h[1] in arm_links]
    assert not blocked, f"{len(blocked)} of {len(hits)} rays meet an arm"


def test_the_parked_arms_stay_clear_of_the_pelvis_as_the_waist_turns(
    centauro: RobotDescription,
) -> None:
    """Centauro's right arm, beside its pelvis with every joint at zero, was left out of the
    draft's parking check there, and the waist turning the head swung it into the pelvis
    (on the convex hulls motions check). Raw PyBullet: the parked arms keep clear of the
    pelvis with the waist at every 15 degrees to 60 each way."""
    loaded = load_description(centauro)
    assert loaded.pan_tilt is not None
    waist = loaded.pan_tilt.pan_joint
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(loaded.urdf), useFixedBase=True, physicsClientId=client)
        joints, links = {}, {}
        for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
            info = pybullet.getJointInfo(body, i, physicsClientId=client)
            joints[info[1].decode()], links[info[12].decode()] = i, i
        for arm in loaded.arms.values():
            for name, value in arm.parking.items():
                pybullet.resetJointState(body, joints[name], value, physicsClientId=client)
        arm_links = [links[n] for a in loaded.arms.values() for n in a.links if n in links]
        nearest = math.inf
        for degrees in range(-60, 61, 15):
            turn = math.radians(degrees)
            pybullet.resetJointState(body, joints[waist], turn, physicsClientId=client)
            for link in arm_links:
                for point in pybullet.getClosestPoints(
                    body, body, 0.05, link, -1, physicsClientId=client
                ):  # -1: the pelvis, the root
                    nearest = min(nearest, point[8])
    finally:
        pybullet.disconnect(client)
    assert nearest > 0.0

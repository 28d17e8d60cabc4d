"""Issue 37: a drafted robot's parked arms keep out of its camera's view as the plans look.

Rollin' Justin's parked right hand kept out of its head camera's view looking straight
ahead only; looking down at the kitchen's counter, panned to the mug, its thumb hid the
mug. The draft now parks the arms clear of every look of a grid (tilted down to the
limit, panned each way), and a hand's fingers meeting one another at their limits no
longer count as the parked arm touching (every stowed pose of Justin's did). Judged with
raw PyBullet: rays from the camera across its field of view, from each look, meet none
of the arms' links.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.robots.description import RobotDescription
from robocram.world import World
from tests.bullet_links import link_indices
from tests.drafts import drafted, drafted_module

JUSTIN = (
    Path(__file__).resolve().parents[1] / "data" / "zoo" / "rollin_justin" / "rollin_justin.urdf"
)
RAYS = 9  # per side of the field of view
REACH = 1.5  # [m] rays this long: the counter in front and the arms beside the body
NEAR = 0.06  # [m] rays start this far out: the head's own housing is not the view


@pytest.fixture(scope="module")
def justin() -> RobotDescription:
    return drafted(JUSTIN).description


@pytest.fixture(scope="module")
def world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[World]:
    """Justin loaded as the plans load it (stand-in palms, its trunk in its stance)."""
    module = drafted_module(JUSTIN, tmp_path_factory.mktemp("justin_looks") / "justin.py")
    world = World()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        world.add_robot(str(module))
    yield world
    world.close()


def _arm_rays_hit(world: World, desc: RobotDescription, pan: float, tilt: float) -> int:
    """How many rays from Justin's camera, its head at ``pan`` and ``tilt`` and its arms
    parked, first meet an arm's link: on PyBullet's own kinematics and shapes."""
    assert desc.pan_tilt is not None
    camera = desc.cameras[0]
    frame = next(f for f in desc.extra_frames if f.name == camera.frame)
    state = {
        **{j: v for arm in desc.arms.values() for j, v in arm.parking.items()},
        desc.pan_tilt.pan_joint: pan,
        desc.pan_tilt.tilt_joint: tilt,
    }
    client, body = world.physics.client(), world.object(desc.name).body_id
    for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
        name = pybullet.getJointInfo(body, i, physicsClientId=client)[1].decode()
        if name in state:
            pybullet.resetJointState(body, i, state[name], physicsClientId=client)
    links = link_indices(body, client)
    head = pybullet.getLinkState(
        body, links[frame.parent], computeForwardKinematics=True, physicsClientId=client
    )
    eye, orientation = pybullet.multiplyTransforms(
        head[4], head[5], frame.pose.position, frame.pose.orientation
    )
    rotation = np.array(pybullet.getMatrixFromQuaternion(orientation)).reshape(3, 3)
    arm_links = {i for name, i in links.items() if name.startswith(("left_", "right_"))}
    starts, ends = [], []  # Justin's arms and hands: every link named by its side
    for a in np.linspace(-camera.horizontal_fov / 2, camera.horizontal_fov / 2, RAYS):
        for b in np.linspace(-camera.vertical_fov / 2, camera.vertical_fov / 2, RAYS):
            direction = np.array((math.tan(a), math.tan(b), 1.0))
            direction = rotation @ (direction / np.linalg.norm(direction))
            starts.append(np.asarray(eye) + direction * NEAR)
            ends.append(np.asarray(eye) + direction * REACH)
    hits = pybullet.rayTestBatch(starts, ends, physicsClientId=client)
    return sum(1 for h in hits if h[0] == body and h[1] in arm_links)


def test_justins_parked_arms_leave_every_look_down_and_aside_clear(
    justin: RobotDescription, world: World
) -> None:
    """Looks every 15 degrees: tilted down 0-45 degrees (its limit, 0.785 rad: the look
    at the counter's mug) and panned -45 to 45 (its limits); none sees an arm."""
    limit = math.radians(45.0)
    blocked = {
        (round(math.degrees(pan)), round(math.degrees(tilt))): hits
        for pan in np.linspace(-limit, limit, 7)
        for tilt in np.linspace(0.0, limit, 4)
        if (hits := _arm_rays_hit(world, justin, float(pan), float(tilt)))
    }
    assert not blocked, f"rays meeting an arm per look (pan, tilt [degrees]): {blocked}"


def test_justins_parking_is_stowed_not_the_sampled_fallback(justin: RobotDescription) -> None:
    """Its fingers meet the palm and thumb at their limits wherever the arm is: counted
    as the arm's touching, every stowed candidate was refused and the sampled pose (hand
    0.76 m out from the base's middle, the left) was kept, with a doubt."""
    why = drafted(JUSTIN).why
    doubts = drafted(JUSTIN).doubts
    for arm in ("left", "right"):
        assert why[f"arms.{arm}.parking"].startswith("stowed")
        assert f"arms.{arm}.parking" not in doubts

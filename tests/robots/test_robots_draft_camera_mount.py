"""A link carrying the camera is not the camera: Tracy's ``camera_pole``.

Tracy's URDF names three frames like cameras: ``camera_pole`` (a metre-tall pole on a
plate, its frame at the pole's foot), ``camera_mount`` on its top and ``camera_link``
below that. The draft took the pole, whose own body blocked every view. A body larger
than any camera that carries other camera frames is their mount now: the draft takes the
camera at the end. Judged in a raw PyBullet: a ray along the camera's optical axis meets
nothing of the robot within a metre.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import PtuGoalNotReached
from robocram.projection.neck import look_at
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robot_check import description_from
from robocram.world import World
from tests.drafts import drafted_module

TRACY = Path(__file__).resolve().parents[1] / "data" / "zoo" / "tracy" / "tracy.urdf"


@pytest.fixture(scope="module")
def tracy(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Tracy's draft, written once for the module's tests (each drafted it, ~0.5 s CPU)."""
    module = tmp_path_factory.mktemp("tracy") / "tracy.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(TRACY, module)
    return module


def test_tracys_drafted_camera_is_the_one_on_the_pole_and_looks_down_onto_its_table(
    tracy: Path,
) -> None:
    """``camera_link`` is not named optical: its x, 72 degrees down, is its axis (the ROS
    body convention), not its z, which looks 18 degrees up over everything. The optical
    axis meets the robot's own table top from above, at its middle (0.59 m ahead)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with World() as world:
            robot = world.add_robot(description_from(str(tracy)))
            camera = robot.description.cameras[0].frame
            client, body = world.physics.client(), world.object(robot.name).body_id
            names = {
                pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
                for i in range(pybullet.getNumJoints(body, physicsClientId=client))
            }
            state = pybullet.getLinkState(
                body, names[camera], computeForwardKinematics=True, physicsClientId=client
            )
            z = np.array(pybullet.getMatrixFromQuaternion(state[5])).reshape(3, 3)[:, 2]
            start = np.asarray(state[4])
            hit = pybullet.rayTest(start, start + 1.5 * z, physicsClientId=client)[0]
            names_by_index = {i: n for n, i in names.items()}
            names_by_index[-1] = pybullet.getBodyInfo(body, physicsClientId=client)[0].decode()
    assert camera == "camera_link_optical"
    assert start[2] > 0.8  # on top of the pole, not at its foot
    assert math.degrees(math.asin(-z[2])) == pytest.approx(72.0, abs=1.0)
    assert hit[0] == body and names_by_index[hit[1]] == "table", hit
    assert hit[4][2] > 0.99  # its top, seen from above
    assert hit[3][0] == pytest.approx(0.59, abs=0.02)


def test_a_camera_nothing_turns_looks_only_at_what_is_in_its_view(tracy: Path) -> None:
    """Tracy's camera is fixed: the plans' look found no process module. A look moves
    nothing now; it passes for a point on the optical axis (PyBullet's camera link state)
    and fails, saying so, for one behind the camera."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with World() as world:
            name = world.add_robot(description_from(str(tracy))).name
            robot = ProjectedRobot.of(world, name)
            camera = robot.description.cameras[0].frame
            client, body = world.physics.client(), world.object(name).body_id
            index = next(
                i
                for i in range(pybullet.getNumJoints(body, physicsClientId=client))
                if pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode() == camera
            )
            state = pybullet.getLinkState(
                body, index, computeForwardKinematics=True, physicsClientId=client
            )
            z = np.array(pybullet.getMatrixFromQuaternion(state[5])).reshape(3, 3)[:, 2]
            before = world.joint_states(name)
            ahead = tuple(float(v) for v in np.asarray(state[4]) + z)
            behind = tuple(float(v) for v in np.asarray(state[4]) - z)
            assert look_at(robot, ahead) == {}
            with pytest.raises(PtuGoalNotReached, match="cannot turn"):
                look_at(robot, behind)
            assert world.joint_states(name) == before

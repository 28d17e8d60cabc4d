"""A palm hand's rim grasp raised, last of all, until the hand keeps over the support as it
closes.

Armar6's open thumb stands 10.5 cm out of its palm, and its 11.6 cm fingers curl round
the wall of a bowl 6.4 cm tall: at the tilted rim grasp the thumb went 12 mm into the bowl
and, closing, the fingers met the drawer's floor before the bowl (issue 37, zoo29). The
hand is put at each grasp by moving the robot, and judged by PyBullet's closest points
between its links and the bowl and a slab the bowl stands on, apart from the grasp model.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.grasping import hand_of, object_shape
from robocram.grasping.grasp import Grasp
from robocram.grasping.grasp_model import grasps
from robocram.grasping.object_grasps import candidates_at
from robocram.tf import Pose
from robocram.world import World
from tests.bullet_links import link_indices
from tests.drafts import drafted_module

ARMAR6 = Path(__file__).resolve().parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"
ARM = "right"
FAR = ((5.0, 5.0, 0.0), (0.0, 0.0, 0.0, 1.0))
HAND_MAY_TOUCH = 0.005  # [m] the pick lets the open hand lie this far in what it grasps
OPPOSED = -0.3  # cos: contact normals this far apart press the bowl from two sides
TOUCH = 0.001  # [m] a link this near the bowl touches it


@pytest.fixture(scope="module")
def armar6(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[World, str]]:
    module = tmp_path_factory.mktemp("armar6") / "armar6.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(ARMAR6, module)
        world = World()
        robot = world.add_robot(str(module)).name
    world.add_item("bowl-1", "bowl", FAR)
    world.add_box("slab", (0.6, 0.6, 0.02), ((5.0, 5.0, -0.01), (0.0, 0.0, 0.0, 1.0)))
    yield world, robot
    world.close()


def _rims(world: World, robot: str) -> list[Grasp]:
    shape = object_shape(world, world.object("bowl-1"))
    hand = hand_of(world.robot(robot).description, ARM)
    return [g for g in grasps(shape, hand, ("rim",)) if g.turn == 0.0]


def _at(world: World, robot: str, grasp: Grasp, fraction: float) -> None:
    """The robot moved so its tool frame lies at ``grasp`` on the bowl, the hand
    ``fraction`` open (the bowl stands at :data:`FAR` on the slab)."""
    desc = world.robot(robot).description
    gripper = desc.arms[ARM].gripper
    assert gripper is not None
    world.set_joint_states(robot, gripper.at(fraction))
    base, tool = world.pose(robot), world.link_pose(robot, desc.arms[ARM].tool_frame)
    tool_in_base = base.inverse() * tool
    world.set_pose(robot, Pose(*FAR) * grasp.tool * tool_in_base.inverse())


def _points(world: World, robot: str, other: str, links: list[str]) -> list[tuple[float, ...]]:
    """PyBullet's closest points (within 5 cm) of ``links`` to ``other``: distance [m]
    (negative: in it), then the normal on ``other``."""
    client = world.physics.client()
    body, indices = world.object(robot).body_id, link_indices(world.object(robot).body_id, client)
    found = []
    for link in links:
        for p in pybullet.getClosestPoints(
            body, world.object(other).body_id, 0.05, indices[link], physicsClientId=client
        ):
            found.append((p[8], *p[7]))
    return found


def _deepest(world: World, robot: str, other: str, links: list[str]) -> float:
    """[m] how deep the deepest of ``links`` lies in ``other`` (negative: clear by so much)."""
    return -min(p[0] for p in _points(world, robot, other, links))


def _hand(world: World, robot: str) -> tuple[list[str], list[str]]:
    """The hand's links PyBullet has (the palm and fingers) and the thumb's among them."""
    spec = world.robot(robot).description.arms[ARM]
    present = link_indices(world.object(robot).body_id, world.physics.client())
    links = [k for k in dict.fromkeys((*spec.hand_links, *spec.gripper_links)) if k in present]
    return links, [k for k in links if k.startswith("Thumb")]


def test_raised_rim_grasps_come_after_every_other(armar6: tuple[World, str]) -> None:
    world, robot = armar6
    shape = object_shape(world, world.object("bowl-1"))
    desc = world.robot(robot).description
    found = candidates_at(shape, Pose(*FAR), desc, ARM, Pose(), ("rim",))
    raised = [c.grasp.raised > 0.0 for c in found]
    assert any(raised) and not all(raised)
    assert raised == sorted(raised)  # every raised one after every other
    rims = _rims(world, robot)
    assert {g.tilt for g in rims if g.raised > 0.0} == {g.tilt for g in rims if g.raised == 0.0}


def test_the_raised_tilted_rim_grasp_keeps_the_hand_out_of_the_bowl_and_the_slab(
    armar6: tuple[World, str],
) -> None:
    world, robot = armar6
    links, thumb = _hand(world, robot)
    rims = _rims(world, robot)
    usual = next(g for g in rims if g.tilt > 0.0 and g.raised == 0.0)
    same = [g for g in rims if g.tool.position[:2] == usual.tool.position[:2]]
    raised = next(g for g in same if g.raised > 0.0 and g.tilt == usual.tilt)
    assert raised.tool.position[2] - usual.tool.position[2] == pytest.approx(raised.raised)
    _at(world, robot, usual, 1.0)
    assert _deepest(world, robot, "bowl-1", thumb) > HAND_MAY_TOUCH  # the thumb in the bowl
    sweep = np.linspace(1.0, 0.0, 21)
    usual_low = []
    for fraction in sweep:
        _at(world, robot, usual, float(fraction))
        usual_low.append(_deepest(world, robot, "slab", links))
    assert max(usual_low) > 0.0  # closing, the hand goes into what the bowl stands on
    _at(world, robot, raised, 1.0)
    assert _deepest(world, robot, "bowl-1", thumb) < HAND_MAY_TOUCH
    gripped = None
    for fraction in sweep:
        _at(world, robot, raised, float(fraction))
        assert _deepest(world, robot, "slab", links) < -0.005  # over it all the way
        touching = [p for p in _points(world, robot, "bowl-1", links) if p[0] <= TOUCH]
        normals = [np.asarray(p[1:]) for p in touching]
        if any(float(a @ b) < OPPOSED for a in normals for b in normals):
            gripped = float(fraction)
            break
    assert gripped is not None and gripped > 0.0  # the bowl pressed from two sides

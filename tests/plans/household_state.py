"""A breakfast household's state, saved as JSON from a run, rebuilt in a fresh scene: the
situation a plan failed in, without the minutes of household before it."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pybullet

from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from robocram.world import World

DATA = Path(__file__).resolve().parents[1] / "data"


def saved_pose(entry: list[list[float]]) -> Pose:
    """A pose saved as ``[position, orientation]``."""
    return Pose(tuple(entry[0]), tuple(entry[1]))


@dataclass(frozen=True)
class Household:
    """The rebuilt world, the robot's name and the saved state (for its other entries)."""

    world: World
    robot: str
    state: dict[str, Any]


def rebuilt(robot: str, file: str) -> Household:
    """``robot``'s breakfast kitchen as ``DATA/file`` saved it: the kitchen's joints, the
    robot's base and joints, the things' poses and what the robot holds (``held``: thing
    -> link, if saved)."""
    state = json.loads((DATA / file).read_text())
    scene = breakfast_scene(robot)
    world = scene.world
    world.set_joint_states("kitchen", state["kitchen_joints"])
    world.set_pose(scene.robot, saved_pose(state["base"]))
    world.set_joint_states(scene.robot, state["joints"])
    for name, entry in state["things"].items():
        world.set_pose(name, saved_pose(entry))
    for name, link in state.get("held", {}).items():
        world.attach(name, scene.robot, link)
    return Household(world, scene.robot, state)


def inside(world: World, thing: str, link: str) -> bool:
    """Whether ``thing``'s origin lies in the bounding box of the kitchen's ``link``, by raw
    PyBullet (the judge of where a plan left a thing)."""
    cid = world.physics.client()
    kitchen = world.object("kitchen").body_id
    index = next(
        j
        for j in range(pybullet.getNumJoints(kitchen, physicsClientId=cid))
        if pybullet.getJointInfo(kitchen, j, physicsClientId=cid)[12].decode() == link
    )
    low, high = pybullet.getAABB(kitchen, index, physicsClientId=cid)
    at, _ = pybullet.getBasePositionAndOrientation(world.object(thing).body_id, physicsClientId=cid)
    return all(lo <= v <= hi for lo, v, hi in zip(low, at, high, strict=True))

"""A small arm whose second joint rises over its pan carries things across its workcell.

The SO-100 (example-robot-data, drafted): its mug comes in to where the hand reaches past
the 0.10 m rise at its shoulder (``test_scenes_tabletop_shoulder_rise.py``); the workcell
put the bowl and the mug's spot 0.15 m aside, as far out, 0.27-0.28 m from its pan's axis,
where the hand reaches 0.235 m. Now they lie on the arc it reaches, and its wrist camera,
aimed from its parked pose, no longer folds its forearm into its base looking for the bowl.
Judged by PyBullet: the items' and spots' distances from the pan's axis (raw link states),
that they lie on the table, and where the mug and the bowl end up.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.scenes import workcell_scene, workcell_spots
from robocram.scenes.placement import WRIST_BELOW_SHOULDER
from tests.so100_rise import drafted_so100, rise

ASIDE = 0.14  # [m] the bowl and the mug's spot lie at least this far aside of the mug
PLACED = 0.02  # [m] an item put down lies this near its spot, across the table
SETTLED = 0.01  # [m] and as high as it rested before


def _position(client: int, body: int) -> tuple[float, float, float]:
    position, _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
    return (float(position[0]), float(position[1]), float(position[2]))


def test_the_so100_carries_the_mug_then_the_bowl_within_reach_past_its_rise(
    tmp_path: Path,
) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = workcell_scene(drafted_so100(tmp_path))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        pan, top, room = rise(body, client)
        items = {n: world.object(n).body_id for n in ("mug-1", "bowl-1")}
        before = {n: _position(client, b) for n, b in items.items()}
        spots = workcell_spots(scene)
        table = world.object(scene.environment).body_id
        low, high = pybullet.getAABB(table, -1, physicsClientId=client)
        mug = before["mug-1"]
        for name, (x, y, _) in {
            "bowl": before["bowl-1"],
            **{f"{n} spot": s.position for n, s in spots.items()},
        }.items():
            wrist = (x, y, pan[2] - WRIST_BELOW_SHOULDER)
            assert math.dist(top, wrist) <= room + 1e-3, name  # 0.27-0.28 m out before
            assert low[0] < x < high[0] and low[1] < y < high[1], name  # on the table
            if name != "bowl-1 spot":  # the bowl goes where the mug stood
                assert abs(y - mug[1]) > ASIDE, name
        with simulated_robot(world, scene.robot):
            for kind, item in (("mug", "mug-1"), ("bowl", "bowl-1")):
                perform(an.action(type="transporting", object=kind, target=spots[item]))
        for item, body_id in items.items():
            x, y, z = _position(client, body_id)
            sx, sy, _ = spots[item].position
            assert math.hypot(x - sx, y - sy) < PLACED, item
            assert z == pytest.approx(before[item][2], abs=SETTLED), item
    finally:
        world.close()

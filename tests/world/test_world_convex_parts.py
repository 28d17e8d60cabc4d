"""A link whose mesh's convex hull overstates it collides as the mesh's convex parts.

Judged on raw PyBullet: Baxter's torso, named in ``decomposed_links``, against a probe
ball where its hull reaches but its mesh does not (clear), and on the mesh's own
vertices (still in contact); the same probe meets the torso loaded as one hull.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import coal
import numpy as np
import pybullet
import pytest

from robocram.motion.coal_shapes import mesh_hulls
from robocram.robots import DescriptionCheckError, RobotModel, load_description
from robocram.robots.convex_parts import with_convex_parts
from robocram.robots.draft.hull_overreach import hull_overreach, overreaching_links
from robocram.robots.draft.model_tree import ModelTree
from robocram.world import World
from robocram.world.convex_parts import convex_parts_file, decomposed
from tests.bullet_links import link_frame, link_indices

ROOT = Path(__file__).resolve().parents[2]
BAXTER = str(ROOT / "examples" / "robots" / "baxter.py")
# [m] in the torso's frame: 0.38 m up, 0.1 m ahead, 0.2 m to the left: the hull fills it
# (it spans the base's front and the chest's), the mesh does not (0.11 m from its surface)
AHEAD = (0.10, 0.20, 0.38)
PROBE = 0.02  # [m] the probe ball's radius


def _distance(world: World, robot: str, link: str, at: np.ndarray, radius: float) -> float:
    """PyBullet's signed distance [m] of a ball at ``at`` (map) to ``link`` of ``robot``."""
    client = world.physics.client()
    body = world.object(robot).body_id
    shape = pybullet.createCollisionShape(
        pybullet.GEOM_SPHERE, radius=radius, physicsClientId=client
    )
    probe = pybullet.createMultiBody(1.0, shape, basePosition=at.tolist(), physicsClientId=client)
    index = link_indices(body, client)[link]
    points = pybullet.getClosestPoints(body, probe, 1.0, linkIndexA=index, physicsClientId=client)
    pybullet.removeBody(probe, physicsClientId=client)
    return min(p[8] for p in points)


def _torso_mesh(model: RobotModel) -> Path:
    return Path(model.links["torso"].collisions[0].geometry.filename)


def test_decomposed_torso_clears_where_only_its_hull_reaches() -> None:
    desc = load_description(BAXTER)
    assert desc.decomposed_links == ("torso", "pedestal")  # as drafted
    distances = {}
    vertices = None
    for links in ((), desc.decomposed_links):
        world = World()
        try:
            robot = world.add_robot(dataclasses.replace(desc, decomposed_links=links)).name
            client = world.physics.client()
            origin, rotation = link_frame(world.object(robot).body_id, client, "torso")
            at = origin + rotation @ np.array(AHEAD)
            distances[links] = _distance(world, robot, "torso", at, PROBE)
            if links:  # the mesh's own vertices, read apart from the decomposition
                mesh = coal.MeshLoader().load(str(_torso_mesh(desc.model)), np.ones(3))
                vertices = np.array(mesh.vertices(), dtype=float).reshape(-1, 3)[::25]
                on_mesh = [
                    _distance(world, robot, "torso", origin + rotation @ v, 0.01) for v in vertices
                ]
        finally:
            world.close()
    assert distances[()] < -0.04  # the hull: the probe 0.06 m deep in it
    assert distances[desc.decomposed_links] > 0.05  # the parts: clear by about 0.1 m
    assert vertices is not None and len(vertices) > 100
    assert max(on_mesh) < 0.0  # a ball on each vertex of the mesh still meets the parts


def test_parts_are_kept_and_the_same_each_time(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path / "a"))
    mesh = _torso_mesh(load_description(BAXTER).model)
    first = convex_parts_file(mesh, (1.0, 1.0, 1.0))
    assert convex_parts_file(mesh, (1.0, 1.0, 1.0)) == first
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path / "b"))  # made again
    again = convex_parts_file(mesh, (1.0, 1.0, 1.0))
    assert again != first and again.read_bytes() == first.read_bytes()
    objects = [line for line in first.read_text().splitlines() if line.startswith("o ")]
    assert len(objects) == 8
    assert len(mesh_hulls(str(first), (1.0, 1.0, 1.0))) == 8  # coal collides it as its parts


def test_draft_names_a_fixed_robots_overreaching_root_links() -> None:
    model = load_description(BAXTER).model
    tree = ModelTree(model)
    found = overreaching_links(tree, fixed=True)
    assert set(found.links) == {"torso", "pedestal"}
    assert "0.17 m" in found.why and "0.27 m" in found.why
    assert overreaching_links(tree, fixed=False).links == ()  # mobile: hulls as before
    assert 0.15 < hull_overreach(_torso_mesh(model), (1.0, 1.0, 1.0)) < 0.2
    panda = load_description(str(ROOT / "examples" / "robots" / "panda.py")).model
    assert overreaching_links(ModelTree(panda), fixed=True).links == ()


def test_builtins_load_unchanged_and_a_link_without_mesh_is_refused() -> None:
    pr2 = load_description("pr2")
    assert pr2.decomposed_links == () and decomposed(pr2) is pr2
    model = load_description(BAXTER).model
    meshless = next(
        name
        for name, link in model.links.items()
        if not any(c.geometry.kind == "mesh" for c in link.collisions)
    )
    with pytest.raises(DescriptionCheckError, match="decomposed_links"):
        with_convex_parts(model, [meshless], lambda mesh, scale: mesh)
    with pytest.raises(DescriptionCheckError, match="decomposed_links"):
        load_description(dataclasses.replace(load_description(BAXTER), decomposed_links=("tors",)))

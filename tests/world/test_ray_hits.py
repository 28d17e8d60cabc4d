"""Array ray casts agree with the per-ray form: bodies, links, hit points and normals."""

from __future__ import annotations

import numpy as np

from robocram.world import World
from robocram.world.ray_hit import ray_hits


def test_rays_down_onto_a_box_hit_its_top_and_miss_beside_it() -> None:
    with World() as world:
        box = world.add_box("crate", (0.4, 0.4, 0.3), (1.0, 0.0, 0.15))
        xs = np.linspace(0.55, 1.45, 10)
        starts = np.column_stack([xs, np.zeros(10), np.full(10, 1.0)])
        ends = starts.copy()
        ends[:, 2] = -0.1
        hits = ray_hits(world, starts, ends)
        on_top = np.abs(xs - 1.0) < 0.2
        assert list(hits.bodies[on_top]) == [box.body_id] * int(on_top.sum())
        assert list(hits.bodies[~on_top]) == [-1] * int((~on_top).sum())
        np.testing.assert_allclose(hits.positions[on_top, 2], 0.3, atol=1e-6)
        np.testing.assert_allclose(hits.normals[on_top], [[0.0, 0.0, 1.0]] * 4, atol=1e-6)
        singles = world.view.ray_cast_batch([tuple(s) for s in starts], [tuple(e) for e in ends])
        for k, single in enumerate(singles):
            if single is None:
                assert hits.bodies[k] == -1
            else:
                assert single.obj.body_id == hits.bodies[k]
                np.testing.assert_allclose(single.position, hits.positions[k], atol=1e-12)


def test_no_rays_give_empty_arrays() -> None:
    with World() as world:
        hits = ray_hits(world, np.zeros((0, 3)), np.zeros((0, 3)))
        assert hits.bodies.shape == (0,) and hits.positions.shape == (0, 3)

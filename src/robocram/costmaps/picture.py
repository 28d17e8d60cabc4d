"""Costmap pictures: the weights over a top-down render of the world, best cells marked."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.grid import CostmapGrid, FloatGrid
from robocram.tf import Pose
from robocram.world import Camera, World

VIEW_HEIGHT = 30.0  # [m] the top-down camera's height: far enough to look almost orthographic
HEAT = np.array((255.0, 40.0, 0.0))  # colour of the highest weight
MARK = (0, 90, 255)


def top_down(
    world: World, extent: tuple[float, float, float, float], size: tuple[int, int]
) -> NDArray[np.uint8]:
    """An RGB render (rows along -y, columns along +x) of the map rectangle ``extent``."""
    x0, x1, y0, y1 = extent
    width, height = size
    optical = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]).T
    m = np.eye(4)
    m[:3, :3] = optical
    m[:3, 3] = ((x0 + x1) / 2, (y0 + y1) / 2, VIEW_HEIGHT)
    hfov = 2 * math.atan((x1 - x0) / 2 / VIEW_HEIGHT)
    vfov = 2 * math.atan((y1 - y0) / 2 / VIEW_HEIGHT)
    camera = Camera(Pose.from_matrix(m), hfov, vfov, near=1.0, far=2 * VIEW_HEIGHT)
    return world.view.render(camera, width, height)


def draw_costmap(
    grid: CostmapGrid,
    weights: FloatGrid,
    marks: list[tuple[int, int]],
    path: str | Path,
    world: World | None,
    pixels_per_cell: int,
) -> Path:
    """Write ``weights`` as a PNG at ``path``, circling the cells ``marks`` (``Costmap.to_png``)."""
    rows, cols = grid.shape
    size = (cols * pixels_per_cell, rows * pixels_per_cell)
    if world is not None:
        background = top_down(world, grid.extent(), size).astype(float)
    else:
        background = np.full((size[1], size[0], 3), 255.0)
    peak = float(weights.max())
    share = np.sqrt(weights / peak) if peak > 0 else weights  # weak cells stay visible
    alpha = np.kron(share[::-1], np.ones((pixels_per_cell, pixels_per_cell)))[..., None]
    blended = np.where(alpha > 0, (1 - 0.75 * alpha) * background + 0.75 * alpha * HEAT,
                       background)  # fmt: skip
    from PIL import Image, ImageDraw  # only a picture needs Pillow; a costmap does not

    image = Image.fromarray(blended.clip(0, 255).astype(np.uint8))
    draw = ImageDraw.Draw(image)
    radius = max(2, pixels_per_cell)
    for row, col in marks:
        cx = (col + 0.5) * pixels_per_cell
        cy = (rows - row - 0.5) * pixels_per_cell
        draw.ellipse((cx - radius, cy - radius, cx + radius, cy + radius), outline=MARK, width=2)
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    image.save(out, format="PNG", optimize=True)
    return out

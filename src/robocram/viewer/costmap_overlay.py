"""A costmap in the 3-D view: one coloured square per cell of positive weight.

The squares lie just above the cells' heights (the floor for where to stand, a table top
for where to put), coloured from dark blue (least likely) to yellow (the best cells) by the
square root of their weight relative to the best cell (costmaps are peaked; the root keeps
the flanks visible), so the view shows why a pose was chosen.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import viser

from robocram.traces import StoredCostmap

LIFT = 0.01  # [m] above the cells' heights, so the floor does not hide the squares
NAME = "/costmap"
# weight (relative to the best cell) -> RGB, interpolated: blue, teal, green, yellow
_STOPS = np.array([0.0, 0.35, 0.7, 1.0])
_COLOURS = np.array([[40, 30, 140], [30, 140, 150], [90, 200, 80], [250, 230, 30]], float)


def colours(relative: np.ndarray) -> np.ndarray:
    """RGB (uint8) for weights relative to the best cell, each in [0, 1]."""
    channels = [np.interp(relative, _STOPS, _COLOURS[:, c]) for c in range(3)]
    return np.stack(channels, axis=1).round().astype(np.uint8)


class CostmapOverlay:
    """Shows at most one costmap at a time in a viser scene."""

    def __init__(self, server: viser.ViserServer) -> None:
        self.server = server
        self.shown: StoredCostmap | None = None
        self.visible = True
        self._handle: Any = None

    def show(self, costmap: StoredCostmap | None) -> None:
        """Draw ``costmap`` instead of the one shown (None: draw none)."""
        if costmap is self.shown:
            return
        if self._handle is not None:
            self._handle.remove()
            self._handle = None
        self.shown = costmap
        if costmap is None:
            return
        points, weights = costmap.cells()
        if len(points) == 0:
            return
        points[:, 2] += LIFT
        self._handle = self.server.scene.add_point_cloud(
            NAME,
            points.astype(np.float32),
            colours(np.sqrt(weights / weights.max())),
            point_size=costmap.resolution,
            point_shape="square",
            precision="float32",
            point_shading="flat",
            visible=self.visible,
        )

    def set_visible(self, visible: bool) -> None:
        """Show or hide the overlay (the costmap stays chosen)."""
        self.visible = visible
        if self._handle is not None:
            self._handle.visible = visible

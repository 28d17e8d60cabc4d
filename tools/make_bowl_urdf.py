"""Write the catalogue's hollow bowl: src/robocram/world/data/bowl.urdf.

A cereal bowl of simple shapes: a bottom disk and a ring of thin wall segments, one link,
so a hand can straddle its wall at the rim (the grasp model's ``rim`` grasp). A solid
cylinder of the same size is 16 cm across, wider than any of our hands opens. The frame
sits on the bottom's underside at the bowl's axis. Run ``python tools/make_bowl_urdf.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

from urdf_shapes import UrdfBuilder, box, cylinder

DATA = Path(__file__).resolve().parents[1] / "src/robocram/world/data"
DIAMETER = 0.16  # [m] outside, at the rim
HEIGHT = 0.06  # [m]
WALL = 0.006  # [m] thickness (the grasp facts' object_wall(bowl, 0.006))
BOTTOM = 0.008  # [m] thickness of the bottom disk
SEGMENTS = 24  # wall segments around the ring
MASS = 0.3  # [kg]
COMMENT = """
  The catalogue's hollow bowl, written by tools/make_bowl_urdf.py (do not edit).
  Its frame is at the bottom's underside on the bowl's axis, z up.
"""


def bowl_urdf() -> str:
    """The bowl's URDF text."""
    outer = DIAMETER / 2
    middle = outer - WALL / 2
    segment = 2 * outer * math.tan(math.pi / SEGMENTS)  # [m] long enough to close the ring
    shapes = [cylinder(outer - WALL / 2, BOTTOM, (0.0, 0.0, BOTTOM / 2))]
    for k in range(SEGMENTS):
        angle = 2 * math.pi * k / SEGMENTS
        centre = (middle * math.cos(angle), middle * math.sin(angle), HEIGHT / 2)
        shapes.append(box(WALL, segment, HEIGHT, centre, (0.0, 0.0, angle)))
    b = UrdfBuilder("bowl", COMMENT)
    b.link("bowl", tuple(shapes), mass=MASS, color="white")
    return b.xml()


def main() -> None:
    """Write the bowl's URDF into the package data."""
    DATA.mkdir(parents=True, exist_ok=True)
    (DATA / "bowl.urdf").write_text(bowl_urdf(), encoding="utf-8")


if __name__ == "__main__":
    main()

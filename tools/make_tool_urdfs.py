"""Write the tool actions' held objects: src/robocram/scenes/tool_data/{cup,knife,spoon}.urdf.

Simple shapes, one link each, so PyBullet collides each piece as it is (a hollow cup
holds particles; a knife is a handle and a thin blade; a spoon a stick and a flat head).
Frames: the cup's at its bottom's underside on its axis; the knife's at its handle's
middle, the blade forward along x with its edge down; the spoon's at its head's
underside, the handle up along z. Run ``python tools/make_tool_urdfs.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

from urdf_shapes import Shape, UrdfBuilder, box, cylinder

DATA = Path(__file__).resolve().parents[1] / "src/robocram/scenes/tool_data"
CUP = {"diameter": 0.07, "height": 0.10, "wall": 0.005, "bottom": 0.006, "segments": 16}
COMMENT = "\n  A tool action's object, written by tools/make_tool_urdfs.py (do not edit).\n"


def cup_urdf() -> str:
    """A hollow cup: a bottom disk and a ring of wall segments."""
    outer = CUP["diameter"] / 2
    wall, height, bottom = CUP["wall"], CUP["height"], CUP["bottom"]
    n = int(CUP["segments"])
    segment = 2 * outer * math.tan(math.pi / n)
    shapes: list[Shape] = [cylinder(outer - wall / 2, bottom, (0.0, 0.0, bottom / 2))]
    for k in range(n):
        angle = 2 * math.pi * k / n
        middle = outer - wall / 2
        centre = (middle * math.cos(angle), middle * math.sin(angle), height / 2)
        shapes.append(box(wall, segment, height, centre, (0.0, 0.0, angle)))
    b = UrdfBuilder("cup", COMMENT)
    b.link("cup", tuple(shapes), mass=0.15, color="blue")
    return b.xml()


def knife_urdf() -> str:
    """A handle (x from -0.05 to 0.05) and a blade 18 cm long, 2 mm thin, 5 cm high."""
    handle = box(0.10, 0.02, 0.02)
    blade = box(0.18, 0.002, 0.05, (0.14, 0.0, -0.02))
    b = UrdfBuilder("knife", COMMENT)
    b.link("knife", (handle, blade), mass=0.08, color="grey")
    return b.xml()


def spoon_urdf() -> str:
    """A flat head at the bottom and a stick 16 cm up."""
    head = box(0.03, 0.02, 0.006, (0.0, 0.0, 0.003))
    stick = box(0.008, 0.008, 0.16, (0.0, 0.0, 0.086))
    b = UrdfBuilder("spoon", COMMENT)
    b.link("spoon", (head, stick), mass=0.03, color="grey")
    return b.xml()


def main() -> None:
    """Write the URDFs into the package data."""
    DATA.mkdir(parents=True, exist_ok=True)
    for name, text in (("cup", cup_urdf()), ("knife", knife_urdf()), ("spoon", spoon_urdf())):
        (DATA / f"{name}.urdf").write_text(text, encoding="utf-8")


if __name__ == "__main__":
    main()

"""Household items by name: pybullet's own mug, our hollow bowl and simple shapes.

Sizes [m] and masses [kg] are those of ordinary kitchen things; an item's type is its
catalogue name. The bowl is hollow (``tools/make_bowl_urdf.py``: a bottom disk and a ring
of wall segments), so a hand can hold it by its rim.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from types import MappingProxyType

import pybullet_data

from robocram.world.body_spec import BodySpec, ShapeSpec, UrdfSpec
from robocram.world.errors import UnknownItemError

PYBULLET_DATA = Path(pybullet_data.getDataPath())  # pybullet's own models
MUG_URDF = PYBULLET_DATA / "objects" / "mug.urdf"
BOWL_URDF = Path(__file__).resolve().parent / "data" / "bowl.urdf"

_ITEMS: Mapping[str, BodySpec] = MappingProxyType(
    {
        "mug": UrdfSpec(MUG_URDF, mass=0.3),
        "pot": ShapeSpec("cylinder", (0.2, 0.2, 0.15), mass=1.2, color=(0.35, 0.35, 0.4, 1)),
        "bottle": ShapeSpec("cylinder", (0.07, 0.07, 0.25), mass=0.6, color=(0.1, 0.6, 0.2, 1)),
        "bowl": UrdfSpec(BOWL_URDF, mass=0.3),  # 0.16 m across, 0.06 m high, 6 mm wall
        "plate": ShapeSpec("cylinder", (0.24, 0.24, 0.02), mass=0.4, color=(0.9, 0.9, 1.0, 1)),
        "cup": ShapeSpec("cylinder", (0.08, 0.08, 0.09), mass=0.15, color=(0.2, 0.3, 0.8, 1)),
        "cereal_box": ShapeSpec("box", (0.07, 0.19, 0.28), mass=0.45, color=(0.95, 0.7, 0.1, 1)),
        "milk": ShapeSpec("box", (0.07, 0.07, 0.2), mass=1.05, color=(1.0, 1.0, 1.0, 1)),
        # flatware as a hand meets it: a handle, as high as a bowl or blade lying in a drawer
        "spoon": ShapeSpec("box", (0.16, 0.035, 0.045), mass=0.05, color=(0.75, 0.75, 0.8, 1)),
        "knife": ShapeSpec("box", (0.22, 0.03, 0.045), mass=0.08, color=(0.6, 0.6, 0.65, 1)),
        "sponge": ShapeSpec("box", (0.1, 0.065, 0.04), mass=0.03, color=(0.95, 0.85, 0.2, 1)),
        "bread": ShapeSpec("box", (0.24, 0.1, 0.1), mass=0.5, color=(0.75, 0.5, 0.25, 1)),
    }
)
_ALIASES: Mapping[str, str] = MappingProxyType(
    {"cereal": "cereal_box", "cereal box": "cereal_box", "loaf": "bread"}
)


def catalogue_names() -> list[str]:
    """The item types :func:`catalogue_item` knows, sorted."""
    return sorted(_ITEMS)


def catalogue_item(kind: str) -> tuple[str, BodySpec]:
    """The canonical type name and body spec of catalogue item ``kind``."""
    name = _ALIASES.get(kind, kind)
    spec = _ITEMS.get(name)
    if spec is None:
        raise UnknownItemError(kind, _ITEMS)
    return name, spec

"""The objects of the tool actions: a hollow cup, a knife, a spoon, a sponge and a loaf.

Each is made of simple shapes so PyBullet collides it as it is: the cup is hollow (it
holds the particles a pour simulates), the knife a handle with a thin blade, the spoon a
stick with a flat head (``tools/make_tool_urdfs.py`` writes their URDFs into
``tool_data/``). The sponge and the loaf are boxes; the bowl is the catalogue's hollow
bowl.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from types import MappingProxyType

from robocram.scenes.errors import SceneError
from robocram.tf import Pose, PoseLike
from robocram.world import ShapeSpec, UrdfSpec, World, WorldObject
from robocram.world.body_spec import BodySpec

REST_GAP = 0.0005  # [m] a resting object's bottom this far over its surface (no contact)
TOOL_DATA = Path(__file__).resolve().parent / "tool_data"
TOOL_SPECS: Mapping[str, BodySpec] = MappingProxyType(
    {
        "cup": UrdfSpec(TOOL_DATA / "cup.urdf", mass=0.15),  # 7 cm across, 10 cm high
        "knife": UrdfSpec(TOOL_DATA / "knife.urdf", mass=0.08),  # 28 cm long
        "spoon": UrdfSpec(TOOL_DATA / "spoon.urdf", mass=0.03),  # 16.6 cm long
        "sponge": ShapeSpec("box", (0.09, 0.06, 0.035), mass=0.02, color=(0.95, 0.85, 0.2, 1)),
        "bread": ShapeSpec("box", (0.10, 0.24, 0.08), mass=0.4, color=(0.75, 0.5, 0.25, 1)),
    }
)


class UnknownToolKind(SceneError):
    """A tool object of a kind this module does not make."""

    def __init__(self, kind: str, known: list[str]) -> None:
        self.kind = kind
        self.known = known
        super().__init__(f"no tool object of kind {kind!r}; use one of {', '.join(known)}")


def tool_kinds() -> list[str]:
    """The kinds :func:`add_tool_object` makes (and ``bowl``, from the catalogue)."""
    return sorted([*TOOL_SPECS, "bowl"])


def add_tool_object(
    world: World, name: str, kind: str, pose: PoseLike, *, on: float | None = None
) -> WorldObject:
    """Add a ``kind`` object called ``name`` at ``pose`` (map; the cup's, knife's and
    spoon's frames are as ``tools/make_tool_urdfs.py`` says, a box's at its middle).

    ``on``: the height [m, map] of the surface it rests on: the pose's height is then
    where its bottom touches that surface. A frame at the middle put at a table's height
    is half in the table: a knife or a sponge put so could not be picked up (every grasp
    had the fingers in the table).

    Raises:
        UnknownToolKind: ``kind`` is none of :func:`tool_kinds`.
    """
    if kind == "bowl":
        added = world.add_item(name, "bowl", pose)
    else:
        spec = TOOL_SPECS.get(kind)
        if spec is None:
            raise UnknownToolKind(kind, tool_kinds())
        added = world.add_object(name, kind, spec, pose)
    if on is not None:
        placed = world.pose(name)
        x, y, z = placed.position
        bottom = world.aabb(name)[0][2]
        world.set_pose(name, Pose((x, y, z + on - bottom + REST_GAP), placed.orientation))
    return added

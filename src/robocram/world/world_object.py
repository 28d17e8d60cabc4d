"""Handles to the bodies of a world: plain objects and robots.

A handle outlives its pybullet body: when a stored state brings back a removed object, the
same handle gets the new body id, so code holding it keeps working.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from robocram.robots import LoadedDescription, RobotModel
from robocram.tf import Pose
from robocram.world.body_spec import BodySpec
from robocram.world.link_pair_rows import LinkPairRows

PAIR_ROWS_KEPT = 8  # sets of link pairs whose rows a handle keeps (one per arm and mode)
ASKED_KEPT = 16  # sets of links whose colliders a handle keeps (per joints, allowed links)
PART_STRIDE = 1024  # link slots per part: part p's link i (pybullet's index) is p * 1024 + i


@dataclass(eq=False)
class WorldObject:
    """A named, typed body of one world; compared by identity.

    ``joint_index`` maps every joint name (fixed ones too) to pybullet's joint index and
    ``link_index`` every link name to its index, the root link mapping to -1 (the base).
    Both are empty for single-shape bodies. A link folded into a host link before loading
    (see :class:`~robocram.world.body_spec.UrdfSpec`) maps to its host's index and keeps
    its pose in the host in ``link_offset``. ``movable_joints`` lists the joints that have
    a state, in index order, read once at load so joint queries need no backend round trip
    per joint.

    A model too big for one pybullet body is several bodies (``parts``, the first being
    ``body_id``), each fixed at ``part_offsets`` (its base link in the root link's frame).
    Link and joint indices are then *slots*: part ``p``'s pybullet index ``i`` is
    ``p * PART_STRIDE + i`` (part 0's slots are pybullet's indices); :meth:`locate` turns a
    slot into ``(body, index)`` and :meth:`slot` back.
    """

    name: str
    type: str
    body_id: int
    spec: BodySpec
    joint_index: dict[str, int] = field(default_factory=dict, kw_only=True)
    link_index: dict[str, int] = field(default_factory=dict, kw_only=True)
    link_offset: dict[str, Pose] = field(default_factory=dict, kw_only=True)
    movable_joints: list[str] = field(default_factory=list, kw_only=True)
    parts: tuple[int, ...] = field(default=(), kw_only=True)
    part_offsets: tuple[Pose, ...] = field(default=(), kw_only=True)
    # the parsed URDF the body was loaded from (None for shapes and meshes), held so that
    # loads of the file share the parse while the body lives (the memo holds models weakly)
    urdf_model: RobotModel | None = field(default=None, kw_only=True, repr=False)
    _index_names: dict[int, str] | None = field(default=None, init=False, repr=False)
    _collider_names: dict[int, str] | None = field(default=None, init=False, repr=False)
    colliders: frozenset[int] = field(default=frozenset(), init=False, repr=False)
    """pybullet link indices that have collision shapes, read when the body is created:
    contact queries leave the others (frames, cameras) out."""
    _pair_rows: dict[tuple[tuple[str, str], ...], LinkPairRows] = field(
        default_factory=dict, init=False, repr=False
    )
    _asked: dict[tuple[str, ...], dict[int, str]] = field(
        default_factory=dict, init=False, repr=False
    )

    @property
    def bodies(self) -> tuple[int, ...]:
        """Every pybullet body of this object, the root part first."""
        return self.parts or (self.body_id,)

    def locate(self, slot: int) -> tuple[int, int]:
        """``(body, pybullet link index)`` of a link slot (see the class docstring)."""
        if not self.parts:
            return self.body_id, slot
        part = (slot + 1) // PART_STRIDE
        return self.parts[part], slot - part * PART_STRIDE

    def slot(self, body: int, index: int) -> int:
        """The link slot of pybullet link ``index`` of ``body``, one of :attr:`bodies`."""
        if not self.parts or body == self.body_id:
            return index
        return self.parts.index(body) * PART_STRIDE + index

    def slots(self) -> list[int]:
        """Every link slot of every part (each part's base too), whether named or not."""
        return sorted(set(self.link_index.values()))

    def forget_indices(self) -> None:
        """Drop what was read from the last body: a new one is being indexed."""
        self._index_names = None
        self._collider_names = None
        self.colliders = frozenset()
        self._pair_rows.clear()
        self._asked.clear()

    def pair_rows(self, pairs: tuple[tuple[str, str], ...]) -> LinkPairRows:
        """``pairs`` of this body's link names as bounds-table rows, kept per set of pairs."""
        found = self._pair_rows.get(pairs)
        if found is None:
            if len(self._pair_rows) >= PAIR_ROWS_KEPT:
                self._pair_rows.clear()
            found = self._pair_rows[pairs] = LinkPairRows.of(self.link_index, pairs)
        return found

    def colliders_among(self, links: tuple[str, ...]) -> dict[int, str]:
        """Index -> name of those of ``links`` that have collision shapes, in their order
        (the last name of an index given twice): kept per tuple of links, as a motion's
        checks ask the same ones each time. Do not change the dict returned."""
        found = self._asked.get(links)
        if found is None:
            if len(self._asked) >= ASKED_KEPT:
                self._asked.clear()
            asked = {self.link_index[name]: name for name in links}
            found = self._asked[links] = {i: n for i, n in asked.items() if i in self.colliders}
        return found

    def collider_names(self) -> dict[int, str]:
        """:meth:`index_names` of the links with collision shapes only (kept per body)."""
        if self._collider_names is None:
            names = self.index_names()
            self._collider_names = {i: n for i, n in names.items() if i in self.colliders}
        return self._collider_names

    def index_names(self) -> dict[int, str]:
        """pybullet link index -> link name (the first name of each index); the base (-1)
        is the object's own name when no link names it. Read once: contact queries ask it
        for every pair they find."""
        if self._index_names is None:
            names: dict[int, str] = {}
            for name, index in self.link_index.items():
                names.setdefault(index, name)
            names.setdefault(-1, self.name)
            self._index_names = names
        return self._index_names

    @property
    def is_static(self) -> bool:
        """Whether the body never moves in simulation (no mass or a fixed base)."""
        return self.spec.is_static

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r}, type={self.type!r}, body={self.body_id})"


@dataclass(eq=False, repr=False)
class RobotObject(WorldObject):
    """A robot body with its checked description (``description.model`` is its URDF)."""

    description: LoadedDescription = field(kw_only=True)

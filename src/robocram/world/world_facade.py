"""What a world's parts and helper modules ask of their world: a few of
:class:`~robocram.world.world.World`'s everyday methods and of its parts.

A protocol, so that the parts and helpers, which ``world.py`` imports, need not import
:class:`World` back (the layering test forbids import cycles, typing ones too).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from contextlib import AbstractContextManager
from typing import Protocol

from robocram.tf import Pose, PoseLike
from robocram.world.attachment import Attachment
from robocram.world.body_spec import BodySpec
from robocram.world.obstacle_boxes import ObstacleBoxes
from robocram.world.versions import Versions
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_tables import ObjectRef
from robocram.world.written_bases import BaseInput


class ClientPart(Protocol):
    """The physics part, as the helpers use it: the client to ask PyBullet with."""

    def client(self) -> int: ...


class OwnersPart(Protocol):
    """The bodies part, as the helpers use it: body ids and attachments."""

    def owner(self, body: int) -> WorldObject | None: ...
    def all_attachments(self) -> list[Attachment]: ...


class StatePart(Protocol):
    """The snapshots part, as the helpers use it: run something and put the world back."""

    def stored_state(self) -> AbstractContextManager[object]: ...
    def bases(self, obj: ObjectRef) -> list[BaseInput]: ...
    def put_bases(self, obj: ObjectRef, bases: Sequence[BaseInput]) -> None: ...


class BoundsPart(Protocol):
    """The contacts part, as the helpers use it: the others' bounds, kept while they stay."""

    def obstacle_boxes(self, ignore: Iterable[ObjectRef] = ()) -> ObstacleBoxes: ...


class WorldFacade(Protocol):
    """The world a part or helper serves."""

    time_step: float  # [s] per physics step

    @property
    def physics(self) -> ClientPart: ...
    @property
    def bodies(self) -> OwnersPart: ...
    @property
    def snapshots(self) -> StatePart: ...
    @property
    def versions(self) -> Versions: ...
    @property
    def contacts(self) -> BoundsPart: ...

    def add_object(
        self, name: str, type: str, spec: BodySpec, pose: PoseLike = ...
    ) -> WorldObject: ...  # noqa: A002
    def object(self, name: ObjectRef) -> WorldObject: ...
    def robot(self, name: ObjectRef) -> RobotObject: ...
    def objects(self, type: str | None = None) -> list[WorldObject]: ...  # noqa: A002
    def pose(self, obj: ObjectRef) -> Pose: ...
    def link_pose(self, obj: ObjectRef, link: str) -> Pose: ...
    def link_names(self, obj: ObjectRef) -> list[str]: ...
    def joint_states(self, obj: ObjectRef) -> dict[str, float]: ...
    def __iter__(self) -> Iterator[WorldObject]: ...

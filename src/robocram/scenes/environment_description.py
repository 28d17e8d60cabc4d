"""An environment description: what plans need to know about a URDF kitchen, as data.

Plans ask the knowledge base for supporting surfaces, containers (the link things lie in,
the joint that opens it, the handle to pull, drawer or door, how far it opens, which way
its front faces) and where a type of object is usually kept. An
:class:`EnvironmentDescription` holds those for one URDF and writes them as the facts of
the predicate table's ``SCENE`` rows (:meth:`EnvironmentDescription.facts`).
``robocram env draft URDF`` drafts one (:mod:`robocram.scenes.environment_draft`); the
built-in kitchen is one too.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

from robocram.logic import name_atom
from robocram.scenes.stand_in import StandIn

ContainerKind = Literal["drawer", "door"]
# the facts of a container, declared (no facts) by an environment without any
CONTAINER_PREDICATES = (
    "container/4",
    "container_kind/3",
    "container_opening/3",
    "container_front/3",
)


@dataclass(frozen=True)
class SurfaceDescription:
    """The top of ``link``: things stand on it ``height`` [m] above the floor.

    ``margin`` [m] is kept from its edges when placing there.
    """

    link: str
    height: float  # [m] in the environment's frame
    margin: float = 0.05  # [m]


@dataclass(frozen=True)
class ContainerDescription:
    """A drawer or door: things lie in ``link``; ``joint`` opens it; ``handle`` is pulled.

    ``opening`` is the joint value [m | rad] that opens it; ``front`` [rad] the yaw (in the
    environment's frame) of the direction out of its front, where the robot stands.
    """

    link: str
    joint: str
    handle: str
    kind: ContainerKind
    opening: float  # [m | rad]
    front: float = 0.0  # [rad]


@dataclass(frozen=True)
class EnvironmentDescription:
    """An environment's URDF and the semantic parts plans use, by link name.

    ``stand_ins`` give shapes to links whose mesh files are missing (a drawer's floor).
    """

    name: str
    urdf: Path
    surfaces: tuple[SurfaceDescription, ...] = ()
    containers: tuple[ContainerDescription, ...] = ()
    usual_locations: tuple[tuple[str, str], ...] = ()  # (object type, surface or container)
    package_paths: tuple[Path, ...] = field(default_factory=tuple)
    stand_ins: tuple[StandIn, ...] = ()

    def surface(self, link: str) -> SurfaceDescription | None:
        """The surface on ``link``, if it is one."""
        return next((s for s in self.surfaces if s.link == link), None)

    def container(self, link: str) -> ContainerDescription | None:
        """The container ``link`` (or whose handle is ``link``), if any."""
        return next((c for c in self.containers if link in (c.link, c.handle)), None)

    def facts(self, environment: str | None = None) -> str:
        """The KB facts (Prolog text) for this environment, named ``environment``."""
        env = name_atom(environment or self.name)
        lines = [f"supporting_surface({env}, {name_atom(s.link)})." for s in self.surfaces]
        if not self.containers:  # asked of every environment: none here is an answer
            lines += [f":- dynamic({p})." for p in CONTAINER_PREDICATES]
        for c in self.containers:
            link = name_atom(c.link)
            lines.append(f"container({env}, {link}, {name_atom(c.joint)}, {name_atom(c.handle)}).")
            lines.append(f"container_kind({env}, {link}, {name_atom(c.kind)}).")
            lines.append(f"container_opening({env}, {link}, {float(c.opening)!r}).")
            lines.append(f"container_front({env}, {link}, {float(c.front)!r}).")
        lines += [
            f"usual_location({name_atom(t)}, {env}, {name_atom(p)})."
            for t, p in self.usual_locations
        ]
        return "\n".join(lines) + "\n"

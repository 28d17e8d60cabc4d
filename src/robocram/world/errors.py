"""The world's exceptions: one root, each subclass carries the data that explains it."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


def did_you_mean(name: str, known: Iterable[str]) -> str:
    """A "; did you mean ...?" hint naming the closest known names, or a list of them."""
    names = sorted(known)
    close = difflib.get_close_matches(name, names, n=3, cutoff=0.5)
    if close:
        return "; did you mean " + " or ".join(repr(c) for c in close) + "?"
    shown = ", ".join(repr(n) for n in names[:8]) + (", ..." if len(names) > 8 else "")
    return f"; known: {shown}" if names else "; there are none"


class WorldError(Exception):
    """Root of every error raised by :mod:`robocram.world`."""


class UnknownObjectError(WorldError):
    """No object of that name is in the world."""

    def __init__(self, name: str, known: Iterable[str]) -> None:
        self.name = name
        self.known = tuple(sorted(known))
        super().__init__(f"no object {name!r} in the world{did_you_mean(name, self.known)}")


class DuplicateObjectError(WorldError):
    """An object of that name already exists."""

    def __init__(self, name: str) -> None:
        self.name = name
        super().__init__(
            f"an object named {name!r} is already in the world; pick another name "
            "or remove the old one first"
        )


class UnknownJointError(WorldError):
    """A joint name that the robot's model does not have (or that cannot move)."""

    def __init__(self, robot_name: str, joint: str, known: Iterable[str], why: str = "") -> None:
        self.robot = robot_name
        self.joint = joint
        self.known = tuple(sorted(known))
        reason = why or f"joint {joint!r} not in {robot_name}'s model"
        super().__init__(f"{reason}{did_you_mean(joint, self.known)}")


class UnknownLinkError(WorldError):
    """A link or frame name that the robot's model does not have."""

    def __init__(self, robot_name: str, link: str, known: Iterable[str]) -> None:
        self.robot = robot_name
        self.link = link
        self.known = tuple(sorted(known))
        super().__init__(
            f"link {link!r} not in {robot_name}'s model{did_you_mean(link, self.known)}"
        )


class UnknownItemError(WorldError):
    """A catalogue item type that does not exist."""

    def __init__(self, kind: str, known: Iterable[str]) -> None:
        self.kind = kind
        self.known = tuple(sorted(known))
        super().__init__(f"no catalogue item {kind!r}{did_you_mean(kind, self.known)}")


class NoCameraError(WorldError):
    """A robot without a camera was asked what it sees."""

    def __init__(
        self, robot_name: str, camera: str | None = None, known: Iterable[str] = ()
    ) -> None:
        self.robot = robot_name
        self.camera = camera
        self.known = tuple(sorted(known))
        if camera is not None and self.known:
            msg = f"robot {robot_name!r} has no camera {camera!r}{did_you_mean(camera, self.known)}"
        else:
            msg = (
                f"robot {robot_name!r} has no camera in its description; "
                "use world.view.visible_from(Camera(pose, ...), obj) instead"
            )
        super().__init__(msg)


class NotARobotError(WorldError):
    """A robot operation on an object that is not a robot."""

    def __init__(self, name: str) -> None:
        self.name = name
        super().__init__(f"{name!r} is not a robot; add it with World.add_robot(...)")


class WorldClosedError(WorldError):
    """The world's physics client was closed."""

    def __init__(self) -> None:
        super().__init__("this World was closed; create a new World() or use world.copy() first")


class WorldValueError(WorldError, ValueError):
    """An argument out of its range (a time step, a duration); the message names it."""

    summary = "a value given to the world is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class BodyLoadError(WorldError):
    """PyBullet could not make a body from a file; the world is left as it was."""

    def __init__(self, name: str, source: str, why: str) -> None:
        self.name = name
        self.source = source
        self.why = why
        super().__init__(f"cannot add {name!r} from {source}: {why}")


class TooManyLinksError(BodyLoadError):
    """A body with more links (or moving joints) than PyBullet can hold, even after a
    fixed-base model was cut into parts at subtrees rigid with its root; ``hint`` says why
    it could not be cut further."""

    def __init__(
        self,
        name: str,
        source: str,
        links: int,
        limit: int,
        what: str = "links below its root",
        hint: str = "",
    ) -> None:
        self.links = links
        self.limit = limit
        self.hint = hint
        why = f" ({hint})" if hint else ""
        super().__init__(
            name,
            source,
            f"it has {links} {what} and PyBullet holds at most {limit} in one body{why}; "
            "hang groups of links (a cabinet with its drawers) on fixed joints from the root "
            "so they load as bodies of their own, or drop links the projection does not need",
        )


class AttachmentCycleError(WorldError):
    """An attachment that would make an object carry itself (A on B, B on A)."""

    def __init__(self, obj: str, carrier: str, chain: list[str]) -> None:
        self.obj = obj
        self.carrier = carrier
        self.chain = tuple(chain)
        loop = " hangs from ".join(repr(name) for name in [*chain, obj])
        super().__init__(
            f"cannot attach {obj!r} to {carrier!r}: {carrier!r} already hangs from {obj!r}, "
            f"so {loop}; detach one of them first"
        )


class WorldUsageError(WorldError, TypeError):
    """The world was handed the wrong kind of thing: the caller's mistake."""

    summary = "the world was handed the wrong kind of thing"
    hint = "pass what the message asks for"

"""Errors of the robots layer: one root, :class:`DescriptionError`, with data-carrying subclasses.

Every message names the culprit (a joint, a link, a file, a URI) and says how to fix it.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol


class DescriptionError(Exception):
    """Root of the robots layer: a robot description or its URDF cannot be used."""


class UrdfError(DescriptionError):
    """A URDF is malformed: not well-formed XML, unsafe XML, or an inconsistent model."""

    def __init__(self, source: str | Path, problem: str, line: int | None = None) -> None:
        self.source = str(source)
        self.problem = problem
        self.line = line
        where = f"{self.source}:{line}" if line is not None else self.source
        super().__init__(f"{where}: {problem}")


class SrdfError(UrdfError):
    """An SRDF is malformed or names links, joints or groups its URDF does not have (a
    robot file's error like a URDF's: where, which line, what to do)."""


class PackageNotFoundError(DescriptionError):
    """A ``package://`` URI names a package found in none of the searched folders."""

    def __init__(self, uri: str, package: str, searched: Iterable[Path]) -> None:
        self.uri = uri
        self.package = package
        self.searched = tuple(searched)
        folders = ", ".join(str(p) for p in self.searched) or "(none)"
        super().__init__(
            f"cannot resolve {uri!r}: package {package!r} not found in {folders}; "
            "pass package_paths=[<folder holding the package>] or add it to ROS_PACKAGE_PATH"
        )


class PackagePathError(DescriptionError):
    """A ``package://`` URI that is no package name, or whose path leaves the package."""

    def __init__(self, uri: str, package: str, why: str) -> None:
        self.uri = uri
        self.package = package
        super().__init__(
            f"refusing {uri!r}: {why}; a package:// path must name a package and stay "
            f"inside its folder (package://<name>/<path below it>)"
        )


@dataclass(frozen=True)
class NameProblem:
    """One name of a description that the robot model does not have."""

    kind: str  # "joint", "link", "frame", "movable joint", "arm"
    name: str
    where: str  # which description field named it, e.g. "arms['right'].joints"
    suggestions: tuple[str, ...]

    def message(self, model_name: str) -> str:
        """Say what is missing and which existing names come closest."""
        text = f"{self.kind} {self.name!r} (in {self.where}) not in {model_name}"
        if self.suggestions:
            options = " or ".join(repr(s) for s in self.suggestions)
            return f"{text}; did you mean {options}?"
        return text


class Problem(Protocol):
    """A problem of a description that can say what is wrong and how to fix it."""

    def message(self, model_name: str) -> str:
        """One line naming the culprit and the fix."""


class DescriptionCheckError(DescriptionError):
    """A description names what its model does not have, or a value that cannot work.

    ``problems`` lists them all: :class:`NameProblem` for names, ``Finding`` (faults of
    the semantic checks) for values.
    """

    def __init__(self, robot_name: str, model_name: str, problems: Iterable[Problem]) -> None:
        self.robot = robot_name
        self.model_name = model_name
        self.problems = tuple(problems)
        lines = [p.message(model_name) for p in self.problems]
        super().__init__(f"description {robot_name!r} fails its check: " + "; ".join(lines))


class JointValueError(DescriptionError):
    """A joint value given in a description lies outside the joint's limits."""

    def __init__(
        self, robot_name: str, joint: str, value: float, lower: float, upper: float
    ) -> None:
        self.robot = robot_name
        self.joint = joint
        self.value = value
        self.lower = lower
        self.upper = upper
        super().__init__(
            f"{robot_name}: value {value} for joint {joint!r} is outside its limits "
            f"[{lower}, {upper}]; pick a value within them"
        )


class LimitValueError(DescriptionError):
    """A limit a description gives (an acceleration limit) is no usable rate."""

    def __init__(self, robot_name: str, joint: str, what: str, value: float, bound: float) -> None:
        self.robot = robot_name
        self.joint = joint
        self.what = what
        self.value = value
        self.bound = bound
        super().__init__(
            f"{robot_name}: {what} {value} for joint {joint!r} is not a finite number of at least "
            f"{bound:g} (MIN_RATE_LIMIT); give the joint's real limit"
        )


def closest_names(name: str, candidates: Iterable[str], n: int = 3) -> tuple[str, ...]:
    """Names among ``candidates`` closest to ``name``: typos first, then substring matches."""
    pool = list(candidates)
    close = difflib.get_close_matches(name, pool, n=n, cutoff=0.6)
    if len(close) < n:
        contained = sorted((c for c in pool if name and name in c and c not in close), key=len)
        close.extend(contained[: n - len(close)])
    return tuple(close)


class DanglingMimicWarning(UserWarning):
    """A ``<mimic>`` names a joint the URDF lacks: the joint is read as moving on its own
    (PyBullet ignores the mimic too), as Boardwalk's Alex hands publish some fingers."""


class MissingMeshWarning(UserWarning):
    """Mesh files of a URDF were not found and boxes stand in for them."""


class GripperDescriptionError(DescriptionError):
    """A gripper description that cannot open or close: a value that makes no sense."""

    def __init__(self, robot_name: str, arm: str, problem: str, fix: str) -> None:
        self.robot = robot_name
        self.arm = arm
        self.problem = problem
        super().__init__(f"{robot_name}: gripper of arm {arm!r}: {problem}; {fix}")


class DescriptionUsageError(DescriptionError, TypeError):
    """A robot description was handed the wrong kind of thing: the caller's mistake."""

    summary = "a robot description was handed the wrong kind of thing"
    hint = "pass what the message asks for"

"""Resolve ``package://pkg/path`` URIs to files, like ROS does, without ROS.

Packages are searched in this order: folders the caller gives, ``ROS_PACKAGE_PATH``, then
the ``share/`` folders of installed prefixes (the Python environment's own and the
``cmeel.prefix`` that pip packages such as ``example-robot-data`` install into). A folder
counts as package ``pkg`` when it is named ``pkg`` and lies at most three levels below a
search root. ``package:///pkg/path`` (an empty first segment, as in example-robot-data's
TALOS) is read as ``package://pkg/path``, as pinocchio reads it: the URDF then loads here
as it does in pinocchio, which robocram's kinematics use.
"""

from __future__ import annotations

import os
import sys
import sysconfig
from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from robocram.robots.errors import PackageNotFoundError, PackagePathError

_MAX_DEPTH = 3


def installed_share_folders() -> tuple[Path, ...]:
    """``share/`` folders of the running environment's prefixes that exist."""
    candidates = [Path(sys.prefix) / "share"]
    for key in ("purelib", "platlib"):
        candidates.append(Path(sysconfig.get_paths()[key]) / "cmeel.prefix" / "share")
    seen: list[Path] = []
    for folder in candidates:
        if folder.is_dir() and folder not in seen:
            seen.append(folder)
    return tuple(seen)


def ros_package_path() -> tuple[Path, ...]:
    """Folders listed in the ``ROS_PACKAGE_PATH`` environment variable."""
    raw = os.environ.get("ROS_PACKAGE_PATH", "")
    return tuple(Path(p) for p in raw.split(os.pathsep) if p)


@lru_cache(maxsize=256)
def _find_package(root: Path, package: str, depth: int = _MAX_DEPTH) -> Path | None:
    """Breadth-first search for a folder named ``package`` under ``root``, at most
    ``depth`` levels down."""
    if root.name == package and root.is_dir():
        return root
    level = [root]
    for _ in range(depth):
        next_level: list[Path] = []
        for folder in level:
            direct = folder / package
            if direct.is_dir():
                return direct
            try:
                next_level.extend(sorted(p for p in folder.iterdir() if p.is_dir()))
            except OSError:
                continue
        level = next_level
    return None


def _check_inside(uri: str, package: str, rest: str) -> None:
    """Refuse package names that are paths and paths that climb out of the package."""
    if package in ("", ".", "..") or os.sep in package or "\\" in package:
        raise PackagePathError(uri, package, f"{package!r} is not a package name")
    norm = os.path.normpath(rest) if rest else "."
    if os.path.isabs(rest) or norm == ".." or norm.startswith(".." + os.sep):
        raise PackagePathError(uri, package, f"{rest!r} leaves the folder of {package!r}")


def _check_relative_inside(uri: str, base_dir: Path, resolved: Path) -> None:
    """Refuse a relative path that climbs out of the package holding the URDF (the nearest
    folder with a ``package.xml``), as ``package://`` paths may not leave theirs."""
    base = base_dir.resolve()
    package = next((p for p in (base, *base.parents) if (p / "package.xml").is_file()), None)
    if package is not None and not resolved.is_relative_to(package):
        raise PackagePathError(uri, package.name, f"{uri!r} leaves the folder of {package.name!r}")


@dataclass(frozen=True)
class PackageResolver:
    """Turns ``package://`` URIs into absolute paths.

    Search order: ``search_roots`` (user folders, ``ROS_PACKAGE_PATH``), then the folders
    around the URDF (so a URDF finds the package it lives in, or one kept beside it: below
    its folder, or next to that folder), then ``installed`` prefixes.
    """

    search_roots: tuple[Path, ...]
    installed: tuple[Path, ...] = ()

    @classmethod
    def default(cls, package_paths: Iterable[str | Path] = ()) -> PackageResolver:
        """Resolver over user folders, then ``ROS_PACKAGE_PATH``, then installed prefixes."""
        roots = [Path(p).expanduser().resolve() for p in package_paths]
        roots += [p.expanduser() for p in ros_package_path()]
        return cls(tuple(dict.fromkeys(roots)), installed_share_folders())

    def package_folder(self, package: str, uri: str = "", near: Path | None = None) -> Path:
        """Folder of ``package``; :class:`PackageNotFoundError` names the searched folders."""
        for root in self.search_roots:
            found = _find_package(root, package)
            if found is not None:
                return found
        if near is not None:
            own = next((p for p in (near, *near.parents) if p.name == package), None)
            if own is not None and own.is_dir():
                return own
            beside = _find_package(near, package) or _find_package(near.parent, package, 1)
            if beside is not None:  # below the URDF's folder, or beside that folder
                return beside
        for root in self.installed:
            found = _find_package(root, package)
            if found is not None:
                return found
        searched = (*self.search_roots, *([near] if near else []), *self.installed)
        raise PackageNotFoundError(uri or f"package://{package}", package, searched)

    def resolve(self, uri: str, base_dir: Path | None = None) -> Path:
        """Absolute path of a ``package://``, ``file://``, absolute or relative reference."""
        if uri.startswith("package://"):
            package, _, rest = uri[len("package://") :].lstrip("/").partition("/")
            _check_inside(uri, package, rest)
            return self.package_folder(package, uri, base_dir) / rest
        if uri.startswith("file://"):
            return Path(uri[len("file://") :])
        path = Path(uri)
        if not path.is_absolute() and base_dir is not None:
            resolved = (base_dir / path).resolve()
            _check_relative_inside(uri, base_dir, resolved)
            return resolved
        return path.resolve()

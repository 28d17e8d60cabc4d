"""Where the mesh and URDF files of a stored scene are found again.

A scene recipe keeps a body's file by its absolute path, which ties the trace to the
checkout (and the virtual environment) that wrote it: the kitchen's URDF of a clone that
has since been removed cannot be loaded, so neither the replay nor the audit can run. A
file inside robocram's own package or pybullet's data is therefore also kept relative to
that package, and read from the package installed now. Stores written before that have only
the absolute path; for them the part after the package's directory is tried in the
installed package.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import robocram
from robocram.traces.errors import SceneFileMissing
from robocram.world.catalogue import PYBULLET_DATA

# the packages whose files a scene names relative to them, by their directory's name
PACKAGES = {
    "robocram": Path(robocram.__file__).resolve().parent,
    "pybullet_data": PYBULLET_DATA.resolve(),
}


def stored_file(path: Path) -> dict[str, str]:
    """The JSON-ready entry for ``path``: ``path`` absolute, and ``package`` (POSIX, the
    package's name first) when the file lies inside one of :data:`PACKAGES`."""
    entry = {"path": str(path)}
    resolved = path.resolve()
    for name, root in PACKAGES.items():
        if resolved.is_relative_to(root):  # else a user's own file: only its path is known
            entry["package"] = f"{name}/{resolved.relative_to(root).as_posix()}"
            break
    return entry


def found_file(body: str, entry: Mapping[str, object]) -> Path:
    """The file of a stored ``entry`` (from :func:`stored_file`, or an older store's bare
    ``path``) as it is on this machine: in the installed package first, then at the stored
    path, then an older store's path re-rooted in the installed package.

    Raises:
        SceneFileMissing: none of these exists.
    """
    path = Path(str(entry["path"]))
    candidates = [*_in_package(Path(str(entry["package"])).parts)] if "package" in entry else []
    candidates += [path, *_in_package(path.parts)]
    for candidate in candidates:
        if candidate.is_file():
            return candidate
    raise SceneFileMissing(body, path)


def _in_package(parts: tuple[str, ...]) -> list[Path]:
    """The tail after each directory named like a package, inside that installed package
    (the innermost first)."""
    return [
        PACKAGES[parts[i]].joinpath(*parts[i + 1 :])
        for i in reversed(range(len(parts) - 1))
        if parts[i] in PACKAGES
    ]

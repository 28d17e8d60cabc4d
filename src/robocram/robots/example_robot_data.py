"""Find the robot models shipped by the PyPI package ``example-robot-data``.

The package installs no importable module into the environment's own site-packages; its
files live under ``cmeel.prefix/share/example-robot-data/robots``. The distribution's file
list says where, so no path is guessed.
"""

from __future__ import annotations

import csv
import os
import re
import sys
from collections.abc import Iterable, Iterator
from functools import lru_cache
from pathlib import Path, PurePosixPath

from robocram.robots.errors import DescriptionError
from robocram.robots.package_resolver import installed_share_folders

DISTRIBUTION = "example-robot-data"


@lru_cache(maxsize=1)
def example_robot_data_folder() -> Path:
    """The ``robots`` folder of ``example-robot-data`` (holding ``pr2_description`` etc.)."""
    files: Iterable[tuple[tuple[str, ...], Path]] | None = _record_files()
    if files is None:
        files = _metadata_files()
    for parts, located in files:
        if "share" in parts and DISTRIBUTION in parts and "robots" in parts:
            relative = Path(*parts[: parts.index("robots") + 1])
            folder = located.parents[len(parts) - len(relative.parts) - 1]
            if folder.is_dir():
                return folder
    for share in installed_share_folders():
        folder = share / DISTRIBUTION / "robots"
        if folder.is_dir():
            return folder
    raise DescriptionError(
        f"the robot models of {DISTRIBUTION!r} are not installed; "
        f"run `pip install {DISTRIBUTION}` in this environment"
    )


def _metadata_files() -> list[tuple[tuple[str, ...], Path]]:
    """Each file the installed distribution lists, as ``importlib.metadata`` finds them:
    its parts and where it is."""
    from importlib import metadata  # ~50 ms with email, zipfile, socket and the listing

    try:
        files = metadata.distribution(DISTRIBUTION).files or []
    except metadata.PackageNotFoundError:
        files = []
    return [(file.parts, Path(str(file.locate()))) for file in files]


def _record_files() -> Iterator[tuple[tuple[str, ...], Path]] | None:
    """What :func:`_metadata_files` gives for a wheel's ``.dist-info`` (the first folder
    of the distribution on ``sys.path``, as ``importlib.metadata`` takes it), read from
    its ``RECORD`` directly, one by one as the folder search takes them; None for anything
    else (an ``.egg-info``, no ``RECORD``)."""
    wanted = _normalized(DISTRIBUTION)
    for entry in sys.path:
        root = Path(entry or ".")
        try:
            names = sorted(os.listdir(root))
        except OSError:
            continue
        for name in names:
            stem, suffix = name.partition("-")[0], Path(name).suffix.lower()
            if suffix not in (".dist-info", ".egg-info") or _normalized(stem) != wanted:
                continue
            if suffix == ".egg-info":
                return None
            try:
                text = (root / name / "RECORD").read_text(encoding="utf-8")
            except OSError:
                return None
            rows = csv.reader(line for line in text.splitlines() if _may_be_a_model(line))
            return ((PurePosixPath(row[0]).parts, root / row[0]) for row in rows if row)
    return None


def _may_be_a_model(line: str) -> bool:
    """False for a file the folder search skips anyway (a cheap test of the words)."""
    return "share" in line and DISTRIBUTION in line and "robots" in line


def _normalized(name: str) -> str:
    return re.sub(r"[-_.]+", "_", name).lower()

"""Find the robot models shipped by the PyPI package ``example-robot-data``.

The package installs no importable module into the environment's own site-packages; its
files live under ``cmeel.prefix/share/example-robot-data/robots``. The distribution's file
list says where, so no path is guessed.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from robocram.robots.errors import DescriptionError
from robocram.robots.package_resolver import installed_share_folders

DISTRIBUTION = "example-robot-data"


@lru_cache(maxsize=1)
def example_robot_data_folder() -> Path:
    """The ``robots`` folder of ``example-robot-data`` (holding ``pr2_description`` etc.)."""
    from importlib import metadata  # ~15 ms with email, zipfile, socket: only when asked

    try:
        files = metadata.distribution(DISTRIBUTION).files or []
    except metadata.PackageNotFoundError:
        files = []
    for file in files:
        parts = file.parts
        if "share" in parts and DISTRIBUTION in parts and "robots" in parts:
            relative = Path(*parts[: parts.index("robots") + 1])
            folder = Path(str(file.locate())).parents[len(parts) - len(relative.parts) - 1]
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

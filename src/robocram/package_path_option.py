"""The ``--package-path`` option the ``robot`` and ``env`` commands share.

Both commands read URDFs whose ``package://`` URIs name ROS packages; one definition keeps
the flag spelled and explained the same in both."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_package_path_option(parser: argparse.ArgumentParser) -> None:
    """Give ``parser`` a repeatable ``--package-path DIR`` (default: none)."""
    parser.add_argument(
        "--package-path",
        type=Path,
        action="append",
        default=[],
        metavar="DIR",
        help="a folder holding ROS packages for package:// URIs (repeatable)",
    )

"""``robocram robot draft``: draft a description from a URDF.

``draft URDF [-o FILE]`` prints (or writes) ready-to-edit Python.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from robocram.robots import draft_description

EXIT_OK = 0


def add_robot_commands(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``robot draft`` and ``robot check`` to the ``robocram`` parser."""
    robot = commands.add_parser("robot", help="bring a new robot in: draft its description")
    sub = robot.add_subparsers(dest="robot_command", required=True, metavar="ACTION")
    draft = sub.add_parser("draft", help="print a description drafted from a URDF")
    draft.add_argument("urdf", type=Path, help="the robot's URDF file")
    draft.add_argument("-o", "--output", type=Path, help="write the Python module here")
    draft.add_argument("--name", help="the robot's name (default: the URDF's)")
    draft.set_defaults(handler=_draft)


def _draft(args: argparse.Namespace) -> int:
    draft = draft_description(args.urdf, name=args.name)
    if args.output is None:
        sys.stdout.write(draft.source())
        return EXIT_OK
    args.output.write_text(draft.source(args.output), encoding="utf-8")
    print(f"wrote {args.output}: edit each TODO doubt, then `robocram robot check {args.output}`")
    return EXIT_OK

"""``robocram robot draft|check``: draft a description from a URDF, and its report card.

``draft URDF [-o FILE] [--srdf FILE]`` prints (or writes) ready-to-edit Python, arms and
parking taken from the SRDF where given; ``check DESCRIPTION`` (``pkg.mod:NAME``, a ``.py``
file, or a built-in robot) drives every part of the robot once in projection and prints one
line per check. Exit code 0 only if all pass. Both take ``--package-path DIR`` (repeatable).
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

from robocram.package_path_option import add_package_path_option

EXIT_OK, EXIT_FAILED = 0, 1


def add_robot_commands(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add ``robot draft`` and ``robot check`` to the ``robocram`` parser."""
    robot = commands.add_parser("robot", help="bring a new robot in: draft and check")
    sub = robot.add_subparsers(dest="robot_command", required=True, metavar="ACTION")
    draft = sub.add_parser("draft", help="print a description drafted from a URDF")
    draft.add_argument("urdf", type=Path, help="the robot's URDF file")
    draft.add_argument("-o", "--output", type=Path, help="write the Python module here")
    draft.add_argument("--name", help="the robot's name (default: the URDF's)")
    draft.add_argument(
        "--srdf", type=Path, help="the robot's SRDF (MoveIt): arms, parking state, self-contacts"
    )
    draft.add_argument(
        "--camera",
        metavar="LINK",
        help="the camera's link, where none is named like one (an optical frame is added "
        "if its x looks ahead)",
    )
    add_package_path_option(draft)
    draft.set_defaults(handler=_draft)
    check = sub.add_parser("check", help="drive every part of a description once: report card")
    check.add_argument(
        "description", help="pkg.module:NAME, a .py file defining description(), or a built-in"
    )
    add_package_path_option(check)
    check.set_defaults(handler=_check)


def _draft(args: argparse.Namespace) -> int:
    from robocram.robots import draft_description

    draft = draft_description(
        args.urdf,
        name=args.name,
        srdf=args.srdf,
        package_paths=args.package_path,
        camera=args.camera,
    )
    if args.output is None:
        sys.stdout.write(draft.source())
        return EXIT_OK
    args.output.write_text(draft.source(args.output), encoding="utf-8")
    print(f"wrote {args.output}: edit each TODO doubt, then `robocram robot check {args.output}`")
    return EXIT_OK


def _check(args: argparse.Namespace) -> int:
    from robocram.robot_check import check_robot, description_from

    desc = description_from(args.description)
    paths = tuple(dict.fromkeys([*desc.package_paths, *args.package_path]))
    card = check_robot(replace(desc, package_paths=paths))
    print(card.render())
    return EXIT_OK if card.passed else EXIT_FAILED

"""``robocram env draft|check``: draft an environment description from a URDF, and its card.

``draft URDF [-o FILE]`` prints (or writes) ready-to-edit Python; ``check FILE`` moves every
container's joint to its opening and back and drops a test item on every surface, one line
per check. Exit code 0 only if all pass.
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

from robocram.package_path_option import add_package_path_option

EXIT_OK, EXIT_FAILED = 0, 1


def add_environment_commands(
    commands: argparse._SubParsersAction[argparse.ArgumentParser],
) -> None:
    """Add ``env draft`` and ``env check`` to the ``robocram`` parser."""
    env = commands.add_parser("env", help="bring a new environment in: draft and check")
    sub = env.add_subparsers(dest="env_command", required=True, metavar="ACTION")
    draft = sub.add_parser("draft", help="print an environment description drafted from a URDF")
    draft.add_argument("urdf", type=Path, help="the environment's URDF file")
    draft.add_argument("-o", "--output", type=Path, help="write the Python module here")
    draft.add_argument("--name", help="the environment's name (default: the URDF's)")
    add_package_path_option(draft)
    draft.set_defaults(handler=_draft)
    check = sub.add_parser("check", help="drive every container and surface once: report card")
    check.add_argument("description", type=Path, help="a .py file defining description()")
    add_package_path_option(check)
    check.set_defaults(handler=_check)


def _draft(args: argparse.Namespace) -> int:
    from robocram.scenes import draft_environment

    draft = draft_environment(args.urdf, name=args.name, package_paths=args.package_path)
    if args.output is None:
        sys.stdout.write(draft.source())
        return EXIT_OK
    args.output.write_text(draft.source(args.output), encoding="utf-8")
    print(f"wrote {args.output}: edit each TODO doubt, then `robocram env check {args.output}`")
    return EXIT_OK


def _check(args: argparse.Namespace) -> int:
    from robocram.scenes.environment_check import check_environment, environment_from

    desc = environment_from(args.description)
    paths = tuple(dict.fromkeys([*desc.package_paths, *args.package_path]))
    card = check_environment(replace(desc, package_paths=paths))
    print(card.render())
    return EXIT_OK if card.passed else EXIT_FAILED

"""Write a drafted environment description as a Python module to edit and keep.

Laid out as ``ruff format`` would (:mod:`robocram.robots.draft.source_writer`), so a kept
draft passes the project's lint and each later edit shows as a few changed lines.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path

from robocram.robots.draft.source_writer import (
    Call,
    Code,
    Item,
    call,
    comment_lines,
    quoted,
    render,
)
from robocram.scenes.environment_description import EnvironmentDescription
from robocram.scenes.stand_in_draft import DraftedStandIn

INDENT = "    "
USUAL_HINT = (
    "where is each type of object usually kept? e.g. "
    'usual_locations=(("bowl", "<a drawer link>"), ("mug", "<a surface link>")),'
)


def environment_source(
    desc: EnvironmentDescription,
    reasons: Mapping[str, str],
    doubts: Sequence[str],
    stand_ins: Sequence[DraftedStandIn] = (),
    module_file: Path | None = None,
) -> str:
    """``desc`` as Python source defining ``description()``; ``# why:`` and doubts inline."""
    urdf = Path(desc.urdf).resolve()
    if module_file is not None:
        relative = os.path.relpath(urdf, Path(module_file).resolve().parent)
        where = f"Path(__file__).resolve().parent / {quoted(Path(relative).as_posix())}"
    else:
        where = f"Path({quoted(urdf.as_posix())})"
    names = ["ContainerDescription", "EnvironmentDescription"]
    names += ["StandIn"] if desc.stand_ins else []
    names += ["SurfaceDescription"]
    body = render(_body(desc, reasons, stand_ins), INDENT, len("return "))
    head, _, last = body.rpartition("\n")
    tail = [*doubts, USUAL_HINT] if not desc.usual_locations else list(doubts)
    todo = [line for d in tail for line in comment_lines(f"TODO doubt: {d}", INDENT * 2)]
    lines = [
        f'"""{desc.name}: an environment description drafted by `robocram env draft` '
        f"from {urdf.name}.",
        "",
        "Check it with `robocram env check THIS_FILE.py`; look at each `TODO doubt`.",
        '"""',
        "",
        "from __future__ import annotations",
        "",
        "from pathlib import Path",
        "",
        "from robocram.scenes import (",
        *[f"    {n}," for n in names],
        ")",
        "",
        f"URDF = {where}",
        "",
        "",
        "def description() -> EnvironmentDescription:",
        f'    """The {desc.name} description (unchecked; `robocram env check` drives it)."""',
        f"    return {head}",
        *todo,
        last,
        "",
    ]
    return "\n".join(lines)


def _body(
    desc: EnvironmentDescription, reasons: Mapping[str, str], drafted: Sequence[DraftedStandIn]
) -> Call:
    fields = [Item("name", desc.name), Item("urdf", Code("URDF"))]
    if desc.package_paths:  # where its meshes were found; as given, or make them relative
        paths = tuple(Code(f"Path({quoted(Path(p).as_posix())})") for p in desc.package_paths)
        fields.append(Item("package_paths", paths, ("why: folders holding its mesh packages",)))
    surfaces = [
        Item(
            None,
            call("SurfaceDescription", s.link, height=s.height),
            (f"why: {reasons.get(s.link, 'named by hand')}",),
        )
        for s in desc.surfaces
    ]
    fields.append(Item("surfaces", Call("(", surfaces, ")", one_tuple=len(surfaces) == 1)))
    containers = [
        Item(
            None,
            call(
                "ContainerDescription",
                c.link,
                c.joint,
                c.handle,
                c.kind,
                opening=c.opening,
                front=c.front,
            ),
            (f"why: {reasons.get(c.link, 'named by hand')}",),
        )
        for c in desc.containers
    ]
    fields.append(Item("containers", Call("(", containers, ")", one_tuple=len(containers) == 1)))
    if desc.stand_ins:
        notes = {d.stand_in: d for d in drafted}
        shapes = []
        for s in desc.stand_ins:
            note = notes.get(s)
            comments = [f"why: {note.why if note else 'named by hand'}"]
            comments += [f"TODO doubt: {note.doubt}"] if note and note.doubt else []
            shape = call("StandIn", s.link, s.kind, size=s.size, centre=s.centre)
            shapes.append(Item(None, shape, tuple(comments)))
        fields.append(Item("stand_ins", Call("(", shapes, ")", one_tuple=len(shapes) == 1)))
    if desc.usual_locations:
        fields.append(Item("usual_locations", desc.usual_locations))
    return call("EnvironmentDescription", *fields)

"""Write a drafted environment description as a Python module to edit and keep."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path

from robocram.scenes.environment_description import EnvironmentDescription


def environment_source(
    desc: EnvironmentDescription,
    reasons: Mapping[str, str],
    doubts: Sequence[str],
    module_file: Path | None = None,
) -> str:
    """``desc`` as Python source defining ``description()``; ``# why:`` and doubts inline."""
    urdf = Path(desc.urdf).resolve()
    if module_file is not None:
        relative = os.path.relpath(urdf, Path(module_file).resolve().parent)
        where = f'Path(__file__).resolve().parent / "{relative}"'
    else:
        where = f'Path("{urdf}")'
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
        "    ContainerDescription,",
        "    EnvironmentDescription,",
        "    SurfaceDescription,",
        ")",
        "",
        f"URDF = {where}",
        "",
        "",
        "def description() -> EnvironmentDescription:",
        f'    """The {desc.name} description (unchecked; `robocram env check` drives it)."""',
        "    return EnvironmentDescription(",
        f"        name={desc.name!r},",
        "        urdf=URDF,",
        "        surfaces=(",
    ]
    for surface in desc.surfaces:
        lines.append(f"            # why: {reasons.get(surface.link, 'named by hand')}")
        lines.append(
            f"            SurfaceDescription({surface.link!r}, height={surface.height!r}),"
        )
    lines += ["        ),", "        containers=("]
    for c in desc.containers:
        lines.append(f"            # why: {reasons.get(c.link, 'named by hand')}")
        lines.append(
            f"            ContainerDescription({c.link!r}, {c.joint!r}, {c.handle!r}, "
            f"{c.kind!r}, opening={c.opening!r}, front={c.front!r}),"
        )
    lines += ["        ),"]
    for doubt in doubts:
        lines.append(f"        # TODO doubt: {doubt}")
    lines += [
        "        # TODO doubt: where is each type of object usually kept? e.g.",
        '        # usual_locations=(("bowl", "<a drawer link>"), ("mug", "<a surface link>")),',
        "    )",
        "",
    ]
    return "\n".join(lines)

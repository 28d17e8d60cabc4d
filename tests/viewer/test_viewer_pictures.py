"""The README's viewer pictures come from the README's own commands: tools/viewer_pictures.py
runs README lines, and each picture carries the command lines that made it."""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path
from types import ModuleType

from PIL import Image

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"


def _pictures_tool() -> ModuleType:
    path = ROOT / "tools" / "viewer_pictures.py"
    spec = importlib.util.spec_from_file_location("viewer_pictures", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while being made
    spec.loader.exec_module(module)
    return module


def _readme_commands() -> list[str]:
    """The lines of the README's ``robocram`` command block, comments cut off, in order."""
    text = README.read_text(encoding="utf-8")
    block = next(b for b in re.findall(r"```bash\n(.*?)```", text, re.S) if "robocram view" in b)
    return [line.split("#")[0].strip() for line in block.splitlines() if line.strip()]


def test_each_picture_is_made_by_readme_lines_in_readme_order() -> None:
    tool = _pictures_tool()
    lines = _readme_commands()
    text = README.read_text(encoding="utf-8")
    for picture in tool.PICTURES:
        run = [*picture.before, picture.command]
        assert all(line in lines for line in run), (run, lines)
        assert [lines.index(line) for line in run] == sorted(lines.index(line) for line in run)
        assert f"]({picture.path})" in text  # the README shows it


def test_each_picture_carries_the_commands_that_made_it() -> None:
    tool = _pictures_tool()
    assert {p.path for p in tool.PICTURES} == {"docs/viewer.png", "docs/viewer_costmap.png"}
    for picture in tool.PICTURES:
        with Image.open(ROOT / picture.path) as image:
            made_by = image.text.get(tool.COMMAND_KEY)  # type: ignore[attr-defined]
            size = image.size
        assert made_by == "\n".join([*picture.before, picture.command]), picture.path
        assert size == (1024, 640)  # the viewer's picture page

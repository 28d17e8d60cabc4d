"""Take the README's viewer pictures by running the README's own commands.

Each picture is one line of the README's ``robocram`` block, run as written (after the
lines it needs, in a fresh folder) with ``--screenshot PICTURE --port FREE`` added: the
command itself opens headless Chromium, waits for the page and saves what it shows. The
command line is written into the PNG (text chunk ``robocram-command``), so a test can check
that each picture came from a line the README still shows. Run
``python tools/viewer_pictures.py`` from the repository root (robocram and Chromium
installed).
"""

from __future__ import annotations

import shlex
import socket
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from PIL import Image
from PIL.PngImagePlugin import PngInfo

ROOT = Path(__file__).resolve().parents[1]
COMMAND_KEY = "robocram-command"  # the PNG text chunk naming the command line


@dataclass(frozen=True)
class Picture:
    """A README picture: the command that shows it, after the commands it needs."""

    path: str  # relative to the repository root, as the README links it
    command: str  # a README line, without its comment
    before: tuple[str, ...] = ()  # README lines run first, in the same folder


PICTURES = (
    Picture("docs/viewer.png", "robocram replay runs.db --run 1", ("robocram demo --db runs.db",)),
    Picture("docs/viewer_costmap.png", "robocram view"),
)


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def _run(line: str, folder: Path, *extra: str) -> None:
    """Run README line ``line`` (``robocram ...``) in ``folder`` with ``extra`` options."""
    words = shlex.split(line)
    if words[0] != "robocram":
        raise ValueError(f"not a robocram command: {line!r}")
    command = [sys.executable, "-m", "robocram.cli", *words[1:], *extra]
    print("$", line, *extra, flush=True)
    subprocess.run(command, cwd=folder, check=True)


def take(picture: Picture) -> Path:
    """Run the picture's commands in a fresh folder; save the PNG with its command line."""
    out = ROOT / picture.path
    with tempfile.TemporaryDirectory(prefix="robocram-pictures-") as folder:
        for line in picture.before:
            _run(line, Path(folder))
        shot = Path(folder) / "picture.png"
        _run(picture.command, Path(folder), "--screenshot", str(shot), "--port", str(_free_port()))
        info = PngInfo()
        info.add_text(COMMAND_KEY, "\n".join([*picture.before, picture.command]))
        with Image.open(shot) as image:
            image.save(out, pnginfo=info, optimize=True)
    return out


if __name__ == "__main__":
    for each in PICTURES:
        print("wrote", take(each))

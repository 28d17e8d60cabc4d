"""The demo (``make demo``) and the example script run end to end, headless and fast."""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

import pytest
from PIL import Image

from robocram import demo


def test_demo_transports_both_items_and_writes_two_pictures_and_a_gif(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    written = demo.main(tmp_path)
    pictures = [tmp_path / "demo_before.png", tmp_path / "demo_after.png"]
    assert written == [*pictures, tmp_path / "demo.gif"]
    with Image.open(tmp_path / "demo.gif") as gif:
        assert gif.format == "GIF" and getattr(gif, "n_frames", 1) > 10  # it moves
    for png in pictures:
        data = png.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n"
        width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
        assert (width, height) == (800, 600)
    printed = capsys.readouterr().out
    assert "✓ kitchen-transport succeeded" in printed
    assert printed.count("✓ perform transporting") == 2
    assert "mug-1 rests on table_top" in printed
    assert "bowl-1 rests on table_top" in printed


def test_example_script_runs(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    example = Path(__file__).resolve().parents[2] / "examples" / "pick_mug.py"
    monkeypatch.setattr(sys, "argv", [str(example), "hsrb"])
    runpy.run_path(str(example), run_name="__main__")
    assert "hsrb: arm arm holds mug-1" in capsys.readouterr().out

"""The demo (``make demo``) and the example script run end to end, headless and fast."""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

import pytest
from PIL import Image

from robocram import demo

GIF_SIZE = (160, 120)  # [px] the GIF's frames here: TinyRenderer took 3/4 of the demo's time
# drawing its 97 frames at the demo's 480 x 360; the frames and their number stay the same


def test_demo_transports_both_items_and_writes_two_pictures_and_a_gif(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(demo, "GIF_SIZE", GIF_SIZE)
    written = demo.main(tmp_path)
    pictures = [tmp_path / "demo_before.png", tmp_path / "demo_after.png"]
    assert written == [*pictures, tmp_path / "demo.gif"]
    with Image.open(tmp_path / "demo.gif") as gif:
        assert gif.format == "GIF" and getattr(gif, "n_frames", 1) > 10  # it moves
        assert gif.size == GIF_SIZE
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


def test_another_robots_files_go_to_its_own_folder(tmp_path: Path) -> None:
    assert demo.output_folder(tmp_path, "pr2", "pr2") == tmp_path  # as the README says
    drafted = Path("examples/robots/tiago_pro.py")
    assert demo.output_folder(tmp_path, str(drafted), "tiago_pro") == tmp_path / "tiago_pro"


def test_a_failed_transport_is_one_line_naming_the_failure() -> None:
    from robocram.plans import FetchExhausted

    failure = FetchExhausted("no stand found for mug-1:\n LocationNotFound: " + "x" * 400)
    line = demo.one_line(failure)
    assert "\n" not in line and line.startswith("FetchExhausted: no stand found for mug-1: ")
    assert len(line) <= len("FetchExhausted: ") + demo.MAX_REASON and line.endswith("...")

"""The draw_house example runs and prints eight strokes and the task tree."""

from __future__ import annotations

import runpy
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "draw_house.py"


def test_draw_house_example_prints_strokes_and_tree(capsys: pytest.CaptureFixture[str]) -> None:
    runpy.run_path(str(EXAMPLE), run_name="__main__")
    out = capsys.readouterr().out
    assert out.count("stroke ") == 8
    assert "draw-house succeeded" in out and out.count("perform moving succeeded") == 9

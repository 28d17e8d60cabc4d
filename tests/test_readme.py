"""The README's example runs as written and detects the mug where the scene put it."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_example_runs(capsys: pytest.CaptureFixture[str]) -> None:
    code = re.search(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    assert code is not None, "the README lost its example"
    namespace: dict[str, object] = {}
    exec(compile(code.group(1), str(README), "exec"), namespace)
    pose = namespace["mug"].get("pose")  # type: ignore[attr-defined]
    assert pose.frame_id == "base_footprint"
    world = namespace["scene"].world  # type: ignore[attr-defined]
    placed = world.pose("pr2").inverse() * world.pose("mug-1")  # the robot stands at the origin
    assert pose.position == pytest.approx(placed.position, abs=1e-3)
    assert placed.position == pytest.approx((0.587, -0.150, 0.616), abs=1e-3)  # see scenes
    world.close()

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
    assert pose.position == pytest.approx((0.62, -0.15, 0.70), abs=1e-3)
    namespace["scene"].world.close()  # type: ignore[attr-defined]

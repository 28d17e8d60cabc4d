"""Every ``python`` block of the docs runs as written, in order, one namespace per page.

A newcomer pastes the blocks of a page one after the other (issue 41): each page's blocks
run here the same way, in a fresh folder. A block that needs what a test cannot give (a
robot, a Ray cluster of yours) says so in the line before it, ``<!-- not run by
tests/test_doc_blocks.py: why -->``, and is left out; the pages named in :data:`ELSEWHERE`
have tests of their own. docs/architecture.md's outlines are ``text`` blocks, not code.
"""

from __future__ import annotations

import contextlib
import io
import shutil
import warnings
from pathlib import Path

import pytest

from tests.doc_blocks import DOCS, runnable_blocks

ROOT = Path(__file__).resolve().parents[1]
ELSEWHERE = {  # page -> the test that runs its blocks
    "queries.md": "tests/test_doc_queries.py",
    "new_robot.md": "tests/test_new_robot_doc.py",
    "activities.md": "tests/plans/test_plans_activities.py",  # its breakfast, then judged
}
PYCRAM = ROOT / "tests" / "data" / "pycram"


def _pages() -> list[str]:
    return sorted(
        p.name
        for p in DOCS.glob("*.md")
        if p.name not in ELSEWHERE and runnable_blocks(p.read_text())
    )


def _prepare(page: str, folder: Path) -> None:
    """What the page's text says the reader has made before its blocks."""
    if page == "new_environment.md":  # "my_kitchen.py being PyCRAM's kitchen as drafted"
        shutil.copy(PYCRAM / "kitchen_env.py", folder / "my_kitchen.py")
        shutil.copy(PYCRAM / "kitchen.urdf", folder / "kitchen.urdf")


def test_every_page_with_code_is_run_here_or_elsewhere() -> None:
    assert set(_pages()) >= {"batch.md", "grasping.md", "locations.md", "motion.md"}
    assert "architecture.md" not in _pages()  # its outlines are text
    for page, test in ELSEWHERE.items():
        assert (ROOT / test).is_file(), page


@pytest.mark.parametrize("page", _pages())
def test_the_blocks_of_a_page_run_as_written(
    page: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    _prepare(page, tmp_path)
    namespace: dict[str, object] = {"__name__": "__main__"}
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        for k, block in enumerate(runnable_blocks((DOCS / page).read_text(encoding="utf-8"))):
            exec(compile(block, f"{page} block {k + 1}", "exec"), namespace)  # noqa: S102

"""Importing a package pulls in only the heavy libraries its import needs (issue 40).

Each import runs in a fresh interpreter and reads ``sys.modules`` afterwards. The plans
only ask the knowledge base and PERFORM designators, so they load none of the heavy
libraries. Projection builds its process modules from the motion and kinematics layers at
import (pinocchio for kinematics, coal for collision shapes, OMPL and ruckig for arm
paths and their timing, PyBullet for the world): those it must load, and nothing more.
Scenes build worlds (PyBullet) and place robots with kinematics (pinocchio, coal). The
batch needs what projection needs; its trace store (SQLAlchemy) only once a batch traces.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
HEAVY = frozenset(
    {"pybullet", "pinocchio", "coal", "ompl", "ruckig", "ray", "sqlalchemy", "viser", "mcap",
     "toppra", "scipy", "trimesh", "PIL", "rclpy"}
)  # fmt: skip
WORLD = frozenset({"pybullet"})
KINEMATICS = frozenset({"pinocchio", "coal"})
MOTION = frozenset({"ompl", "ruckig"})
# package -> the heavy libraries importing it must load (see the module's docstring)
NEEDED: dict[str, frozenset[str]] = {
    "robocram.plans": frozenset(),
    "robocram.projection": WORLD | KINEMATICS | MOTION,
    "robocram.scenes": WORLD | KINEMATICS,
    "robocram.batch": WORLD | KINEMATICS | MOTION,
}


def _fresh(code: str) -> str:
    """The last line ``code`` prints, run in a fresh interpreter on this checkout."""
    path = os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")])
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True,
        env={**os.environ, "PYTHONPATH": path},
    )  # fmt: skip
    return done.stdout.strip().splitlines()[-1]


def _heavy_loaded(module: str) -> set[str]:
    """The heavy libraries in ``sys.modules`` after importing ``module`` in a fresh process."""
    code = (
        f"import json, sys, {module}; "
        f"print(json.dumps(sorted(m for m in {sorted(HEAVY)!r} if m in sys.modules)))"
    )
    return set(json.loads(_fresh(code)))


def test_plans_load_no_heavy_library() -> None:
    assert _heavy_loaded("robocram.plans") == set()


@pytest.mark.parametrize("module", ["robocram.projection", "robocram.scenes", "robocram.batch"])
def test_projection_and_scenes_load_only_what_they_need(module: str) -> None:
    assert _heavy_loaded(module) == NEEDED[module]


def test_drafting_is_loaded_when_asked_for() -> None:
    code = (
        "import sys, robocram.robots, robocram.scenes; "
        "assert 'robocram.robots.draft' not in sys.modules; "
        "from robocram.robots import draft_description, DraftDescription; "
        "from robocram.robots.draft.draft_description import draft_description as made; "
        "assert draft_description is made and isinstance(DraftDescription, type); print('ok')"
    )
    assert _fresh(code) == "ok"

"""Importing a package pulls in none of the heavy libraries until they are used (issue 40).

Each import runs in a fresh interpreter and reads ``sys.modules`` afterwards. The plans
only ask the knowledge base and PERFORM designators. Projection, scenes and the batch
build worlds (PyBullet), kinematics (pinocchio, coal) and arm paths (OMPL, ruckig), but
each module binds those as a :class:`~robocram.robots.lazy_library.LazyLibrary`, imported
at its first use: a script pays for each when it first needs it (PyBullet with its first
world, pinocchio and coal with its first robot in a scene, whose kinematic model the scene
builds), not when it imports.
The batch's trace store (SQLAlchemy) loads only once a batch traces, its progress bar
(tqdm, with ``importlib.metadata``) only once one is shown.
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
     "toppra", "scipy", "trimesh", "PIL", "rclpy", "tqdm", "importlib.metadata"}
)  # fmt: skip


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


@pytest.mark.parametrize(
    "module",
    ["robocram.plans", "robocram.projection", "robocram.scenes", "robocram.batch",
     "robocram.plans, robocram.projection, robocram.scenes"],
)  # fmt: skip
def test_import_loads_no_heavy_library(module: str) -> None:
    assert _heavy_loaded(module) == set()


def test_a_lazy_library_is_the_library_once_used() -> None:
    code = (
        "import sys, robocram.motion.collision_scene as m, robocram.world.pybullet_backend as b; "
        "assert 'pinocchio' not in sys.modules and 'pybullet' not in sys.modules; "
        "import pinocchio; assert m.pin.SE3 is pinocchio.SE3 and 'pinocchio' in sys.modules; "
        "assert b.pybullet.getNumBodies is sys.modules['pybullet'].getNumBodies; print('ok')"
    )
    assert _fresh(code) == "ok"


def test_drafting_is_loaded_when_asked_for() -> None:
    code = (
        "import sys, robocram.robots, robocram.scenes; "
        "assert 'robocram.robots.draft' not in sys.modules; "
        "from robocram.robots import draft_description, DraftDescription; "
        "from robocram.robots.draft.draft_description import draft_description as made; "
        "assert draft_description is made and isinstance(DraftDescription, type); print('ok')"
    )
    assert _fresh(code) == "ok"


def test_a_scene_builds_its_robot_s_kinematics_so_the_first_plan_does_not() -> None:
    code = (
        "import sys; from robocram.scenes import tabletop_scene; "
        "assert 'pinocchio' not in sys.modules; "
        "tabletop_scene('pr2'); "
        "print(sorted(m for m in ('pinocchio', 'coal') if m in sys.modules))"
    )
    assert _fresh(code) == "['coal', 'pinocchio']"


def test_setting_up_a_robot_s_projection_loads_no_drafter() -> None:
    """Every projection asks whether its robot stands on legs it can bend (the draft's
    ``stance.legs``); that must not load the whole drafter (28 modules) into a plan."""
    code = (
        "import sys; from robocram.scenes import tabletop_scene; "
        "from robocram.projection import simulated_robot; "
        "scene = tabletop_scene('pr2'); "
        "ctx = simulated_robot(scene.world, scene.robot); ctx.__enter__(); "
        "print(sorted(m for m in sys.modules if m.startswith('robocram.robots.draft')))"
    )
    assert _fresh(code) == (
        "['robocram.robots.draft', 'robocram.robots.draft.hands', "
        "'robocram.robots.draft.link_poses', 'robocram.robots.draft.model_tree', "
        "'robocram.robots.draft.stance']"
    )

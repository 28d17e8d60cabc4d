"""``robocram`` starts at once: ``--help`` loads no heavy library, and PyBullet is quiet.

Issue 27, item 4: ``robocram --help`` took 1.8-2.6 s because the batch, viewer, database and
physics libraries loaded up front (1,102 modules), and every command printed PyBullet's
build-time banner. Start-up is counted in modules, in a fresh interpreter, not timed.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import robocram.cli
import robocram.traces

HEAVY = ("pybullet", "sqlalchemy", "ray", "numpy", "pinocchio", "viser", "mcap", "PIL", "yaml")
MAX_MODULES = 150  # a bare interpreter here has about 60; --help needed 94 when this was set
BANNER = "pybullet build time"


def _python(code: str, *args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    return subprocess.run(
        [sys.executable, "-c", code, *args], env=env, capture_output=True, text=True, check=True
    )


def test_help_loads_no_heavy_library_and_few_modules() -> None:
    code = (
        "import sys\nfrom robocram.cli import main\n"
        "try:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
        "print('MODULES', ' '.join(sys.modules))"
    )
    out = _python(code).stdout
    assert "usage: robocram" in out
    modules = out.split("MODULES ", 1)[1].split()
    loaded = sorted({m.split(".")[0] for m in modules} & set(HEAVY))
    assert loaded == []
    print(f"robocram --help: {len(modules)} modules")
    assert len(modules) <= MAX_MODULES


def test_each_subcommand_help_loads_no_heavy_library() -> None:
    code = (
        "import sys\nfrom robocram.cli import main\n"
        "for command in sys.argv[1:]:\n"
        "    try:\n        main([*command.split(), '--help'])\n"
        "    except SystemExit:\n        pass\n"
        "print('MODULES', ' '.join(sys.modules))"
    )
    commands = ("demo", "runs list", "runs show", "batch", "view", "replay", "robot draft")
    out = _python(code, *commands).stdout
    modules = out.split("MODULES ", 1)[1].split()
    assert sorted({m.split(".")[0] for m in modules} & set(HEAVY)) == []


def test_pybullet_loads_without_its_banner(tmp_path: Path) -> None:
    code = "import sys\nfrom robocram.world.pybullet_backend import pybullet\n"
    loaded = _python(code + "pybullet.getNumBodies\nprint('pybullet' in sys.modules)")
    assert loaded.stdout == "True\n"
    assert BANNER not in loaded.stderr
    db = tmp_path / "runs.db"
    robocram.traces.TraceDatabase(db).close()
    listed = _python("from robocram.cli import run\nrun()", "runs", "list", str(db))
    assert listed.stdout.startswith("  run  name")
    assert BANNER not in listed.stdout + listed.stderr


def test_the_trace_option_names_the_variable_the_tracer_reads() -> None:
    assert robocram.cli.TRACE_ENV == robocram.traces.TRACE_ENV

"""The example-robot-data folder is found from the wheel's RECORD without
``importlib.metadata``, and the files read that way are those ``importlib.metadata`` lists."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from robocram.robots import example_robot_data as erd

SRC = Path(__file__).resolve().parents[2] / "src"


def test_record_files_are_what_importlib_metadata_lists() -> None:
    read = erd._record_files()
    assert read is not None
    listed = [
        (parts, where)
        for parts, where in erd._metadata_files()
        if "share" in parts and erd.DISTRIBUTION in parts and "robots" in parts
    ]
    assert list(read) == listed and len(listed) > 100


def test_the_folder_is_found_without_importlib_metadata() -> None:
    code = (
        "import sys\nfrom robocram.robots.example_robot_data import example_robot_data_folder\n"
        "folder = example_robot_data_folder()\n"
        "print((folder / 'pr2_description' / 'urdf').is_dir(), 'importlib.metadata' in sys.modules)"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True,
        env={"PYTHONPATH": str(SRC), "PATH": "/usr/bin:/bin"},
    )  # fmt: skip
    assert done.stdout.split() == ["True", "False"]

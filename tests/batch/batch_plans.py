"""Plans for the batch fault tests, imported by name in the spawned workers."""

from __future__ import annotations

import os
import time
from pathlib import Path

from robocram.plans import pick_up
from robocram.tf import PoseStamped

BLOCK_LIMIT = 120.0  # [s] a blocked plan gives up after this, should a test not end it


def pick_or_block(look_target: PoseStamped, block_in: str = "") -> object:
    """Pick up the mug, or (with ``block_in``) write this pid there and wait to be killed."""
    if not block_in:
        return pick_up(look_target)
    Path(block_in).write_text(str(os.getpid()), encoding="utf-8")
    end = time.monotonic() + BLOCK_LIMIT
    while time.monotonic() < end:
        time.sleep(0.05)
    raise TimeoutError(f"nobody killed worker {os.getpid()} within {BLOCK_LIMIT} s")

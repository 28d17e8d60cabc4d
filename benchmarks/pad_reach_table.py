"""Where each zoo robot's finger pads end along its approach, and who gets deep rim grasps.

Run: ``.venv/bin/python benchmarks/pad_reach_table.py [NAME ...]`` (default: the whole
corpus of ``robot_zoo.py``, drafted as there). Per arm with fingers: ``Hand.pads_behind``
[mm] (behind the tool frame; negative: past it), the milliseconds reading the hand took,
and whether its rim grasps come again deep (``grasp_model.PADS_BEHIND_DEEP``). A palm hand
(its rim grasps tilt instead) and a suction or fingerless hand are named as such.
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

from robot_zoo import CORPUS, _draft

from robocram.grasping import GraspingError, hand_of
from robocram.grasping.grasp_model import PADS_BEHIND_DEEP
from robocram.robots import load_description

OUT = Path("/tmp/pad_reach_drafts")


def main(names: list[str]) -> None:
    for robot in CORPUS:
        if names and robot.name not in names:
            continue
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                desc = load_description(_draft(robot, OUT))
        except Exception as error:  # noqa: BLE001 - a draft that fails is a row too
            print(f"{robot.name:16} draft failed: {type(error).__name__}")
            continue
        for arm in desc.arms:
            start = time.perf_counter()
            try:
                hand = hand_of(desc, arm)
            except GraspingError:
                print(f"{robot.name:16} {arm:8} no fingers")
                continue
            ms = (time.perf_counter() - start) * 1000
            if hand.suction or hand.palm is not None:
                kind = "suction" if hand.suction else "palm hand"
                print(f"{robot.name:16} {arm:8} {kind}")
                continue
            deep = hand.pads_behind >= PADS_BEHIND_DEEP
            print(
                f"{robot.name:16} {arm:8} pads end {hand.pads_behind * 1000:6.1f} mm behind"
                f"  ({ms:5.0f} ms)  deep rim grasps: {'yes' if deep else 'no'}",
                flush=True,
            )


if __name__ == "__main__":
    main(sys.argv[1:])

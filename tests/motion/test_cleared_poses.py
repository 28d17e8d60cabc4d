"""The exact check's kept answers: the same pose gets the same answer, a pose within a
cleared pose's gap is cleared with what is left of it, anything else is asked again."""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.motion.cleared_poses import ClearedPoses


def test_answers_follow_from_the_gaps_kept() -> None:
    kept = ClearedPoses(reach=0.5)
    assert kept.known(np.array([0.0, 0.0, 0.0])) == (False, None)
    kept.add(np.array([0.0, 0.0, 0.0]), 0.04)
    kept.add(np.array([1.0, 0.0, 0.0]), None)  # blocked
    kept.add(np.array([2.0, 0.0, 0.0]), 0.0)  # cleared, but no gap to lend
    assert kept.known(np.array([0.0, 0.0, 0.0])) == (True, 0.04)
    assert kept.known(np.array([1.0, 0.0, 0.0])) == (True, None)
    assert kept.known(np.array([2.0, 0.0, 0.0])) == (True, 0.0)
    assert kept.known(np.array([2.001, 0.0, 0.0])) == (False, None)
    near, gap = kept.known(np.array([0.01, 0.0, 0.02]))  # 1 cm, and 0.5 m x 0.02 rad
    assert near and gap == pytest.approx(0.04 - 0.01 - 0.01)
    assert kept.known(np.array([0.0, 0.03, 0.0]))[1] == pytest.approx(0.01)
    assert kept.known(np.array([0.0, 0.04, 0.0])) == (False, None)  # the gap used up
    turned = kept.known(np.array([0.0, 0.0, 2.0 * math.pi + 0.01]))  # a whole turn more
    assert turned[0] and turned[1] == pytest.approx(0.04 - 0.005)

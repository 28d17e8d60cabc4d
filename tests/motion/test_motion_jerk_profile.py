"""Ruckig's profile as tables: the states ruckig gives, bit for bit, past its end too."""

from __future__ import annotations

import numpy as np
from ruckig import InputParameter, Result, Ruckig, Synchronization, Trajectory

from robocram.motion.jerk_profile import jerk_profile


def _profile(rng: np.random.Generator, synchronization: Synchronization) -> Trajectory:
    params = InputParameter(5)
    params.current_position = rng.uniform(-1.0, 1.0, 5).tolist()
    params.target_position = (rng.uniform(-1.0, 1.0, 5) * (rng.random(5) > 0.2)).tolist()
    params.max_velocity = rng.uniform(0.5, 2.0, 5).tolist()
    params.max_acceleration = rng.uniform(1.0, 5.0, 5).tolist()
    params.max_jerk = rng.uniform(5.0, 50.0, 5).tolist()
    params.synchronization = synchronization
    trajectory = Trajectory(5)
    assert Ruckig(5).calculate(params, trajectory) in (Result.Working, Result.Finished)
    return trajectory


def test_the_tables_give_ruckigs_states_bit_for_bit() -> None:
    rng = np.random.default_rng(11)
    for synchronization in (Synchronization.Phase, Synchronization.Time, Synchronization.No):
        for _ in range(15):
            trajectory = _profile(rng, synchronization)
            profile = jerk_profile(trajectory)
            assert profile is not None
            end = trajectory.duration
            times = np.concatenate((np.linspace(0.0, end, 40), rng.uniform(0.0, end, 20), [end]))
            states = profile.states(times)
            assert profile.positions(times).tolist() == states[0].tolist()
            for row, t in enumerate(times):
                want = trajectory.at_time(float(t))
                assert [states[k][row].tolist() for k in range(3)] == [list(w) for w in want]

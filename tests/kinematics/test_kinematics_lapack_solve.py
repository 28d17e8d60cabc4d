"""The descent's linear solve: LAPACK's gesv called directly gives what ``np.linalg.solve``
gives, bit for bit, so a numpy without the private module (the public fallback) changes
no IK answer."""

from __future__ import annotations

import numpy as np

from robocram.kinematics import descent


def test_the_direct_solve_and_the_public_one_agree_bit_for_bit() -> None:
    rng = np.random.default_rng(7)
    for width in (6, 7, 8):
        for _ in range(50):
            jac = rng.normal(size=(6, width))
            hessian = jac.T @ jac
            hessian.flat[:: width + 1] += 1e-3  # the descent's damping keeps it regular
            rhs = rng.normal(size=width)
            fast = descent._gesv(hessian, rhs)
            assert np.array_equal(fast, descent._public_solve(hessian, rhs))
            assert np.allclose(hessian @ fast, rhs, atol=1e-9)

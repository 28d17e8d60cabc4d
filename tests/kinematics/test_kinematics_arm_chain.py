"""An arm chain's shortcuts give what the plain products give, bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from robocram.kinematics import IKSolver


@pytest.mark.parametrize(
    ("robot", "arm", "torso"),
    [("pr2", "left", False), ("pr2", "right", True), ("hsrb", "arm", True)],
)
def test_configuration_and_jacobian_match_the_products_with_a(
    robot: str, arm: str, torso: bool
) -> None:
    chain = IKSolver.cached(robot, arm, torso).chain
    rng = np.random.default_rng(3)
    b = chain.offsets({})
    for _ in range(20):
        x = rng.uniform(-1.0, 1.0, len(chain.variables))
        values = chain.a @ x + b
        q = chain.configuration(x, b)
        assert q[chain.rev_q].tolist() == values[chain.rev_rows].tolist()
        assert q[chain.cos_q].tolist() == np.cos(values[chain.cont_rows]).tolist()
        jac = rng.normal(size=(6, len(chain.path)))
        mapped = chain.variable_jacobian(jac)
        assert mapped.tolist() == (jac @ chain.a).tolist()
        err = rng.normal(size=6)
        assert (mapped.T @ err).tolist() == ((jac @ chain.a).T @ err).tolist()  # same layout

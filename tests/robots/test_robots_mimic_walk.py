"""mimic_followers walks only the model's mimic joints (kept with the model): the values
and their order are those of a walk over every joint, as it was, on every built-in robot
and on a chain whose followers are declared before their masters."""

from __future__ import annotations

import random
from collections.abc import Mapping

import pytest

from robocram.robots import RobotModel, load_description, mimic_followers

BACKWARDS_URDF = """<robot name="backwards"><link name="a"/><link name="b"/><link name="c"/>
  <link name="d"/><link name="e"/>
  <joint name="last" type="revolute"><parent link="c"/><child link="d"/>
    <limit lower="-3" upper="3"/><mimic joint="middle" multiplier="-1" offset="0.2"/></joint>
  <joint name="middle" type="revolute"><parent link="b"/><child link="c"/>
    <limit lower="-3" upper="3"/><mimic joint="master" multiplier="2" offset="0.1"/></joint>
  <joint name="master" type="revolute"><parent link="a"/><child link="b"/>
    <limit lower="-1" upper="1"/></joint>
  <joint name="free" type="revolute"><parent link="a"/><child link="e"/>
    <limit lower="-1" upper="1"/></joint>
</robot>"""


def _every_joint(model: RobotModel, values: Mapping[str, float]) -> dict[str, float]:
    """The walk over all of the model's joints, pass after pass (the reference)."""
    result = dict(values)
    changed = True
    while changed:
        changed = False
        for joint in model.joints.values():
            mimic = joint.mimic
            if mimic is None or mimic.joint not in result or joint.name in result:
                continue
            result[joint.name] = mimic.multiplier * result[mimic.joint] + mimic.offset
            changed = True
    return result


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_same_values_in_the_same_order_as_a_walk_over_every_joint(robot: str) -> None:
    model = load_description(robot).model
    assert model is not None
    masters = sorted({j.mimic.joint for j in model.joints.values() if j.mimic is not None})
    plain = [n for n, j in model.joints.items() if j.mimic is None and j.type != "fixed"]
    rng = random.Random(7)
    for _ in range(20):
        names = rng.sample(masters, rng.randint(0, len(masters))) + rng.sample(plain, 3)
        values = {name: rng.uniform(-0.5, 0.5) for name in names}
        found = mimic_followers(model, values)
        expected = _every_joint(model, values)
        assert list(found) == list(expected)  # the same keys, in the same order
        assert all(found[k] == expected[k] for k in expected)  # to the bit


def test_followers_declared_before_their_masters() -> None:
    model = RobotModel.from_string(BACKWARDS_URDF)
    found = mimic_followers(model, {"master": 0.5, "free": 0.3})
    assert list(found) == ["master", "free", "middle", "last"]  # a second pass adds "last"
    assert found == _every_joint(model, {"master": 0.5, "free": 0.3})
    assert found["last"] == pytest.approx(-(2 * 0.5 + 0.1) + 0.2)
    assert mimic_followers(model, {"free": 0.3}) == {"free": 0.3}  # no master: no follower


def test_each_model_walks_its_own_mimic_joints() -> None:
    """The kept list belongs to its model: another model's followers are its own."""
    backwards = RobotModel.from_string(BACKWARDS_URDF)
    chain = RobotModel.from_string(BACKWARDS_URDF.replace('multiplier="2"', 'multiplier="3"'))
    assert mimic_followers(backwards, {"master": 0.5})["middle"] == pytest.approx(1.1)
    assert mimic_followers(chain, {"master": 0.5})["middle"] == pytest.approx(1.6)
    assert mimic_followers(backwards, {"master": 0.5})["middle"] == pytest.approx(1.1)

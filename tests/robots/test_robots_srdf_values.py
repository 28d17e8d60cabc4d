"""An SRDF group state's values are finite numbers within their joints' limits: a state may
become the parking pose (issue 42, weak: SRDF values)."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from robocram.robots import MissingMeshWarning, RobotModel, SrdfError
from robocram.robots.srdf import read_srdf

FETCH = Path(__file__).resolve().parents[1] / "data" / "fetch"
FETCH_URDF = FETCH / "fetch_description" / "robots" / "fetch.urdf"
FETCH_SRDF = FETCH / "fetch_moveit_config" / "config" / "fetch.srdf"


@pytest.fixture(scope="module")
def fetch() -> RobotModel:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        return RobotModel.from_file(FETCH_URDF, missing_packages_as_boxes=True)


def _with_state(tmp_path: Path, joint: str, value: str) -> Path:
    state = f'<group_state name="tuck" group="arm"><joint name="{joint}" value="{value}"/>'
    text = FETCH_SRDF.read_text("utf-8").replace("</robot>", state + "</group_state></robot>")
    path = tmp_path / "fetch.srdf"
    path.write_text(text, "utf-8")
    return path


def test_a_state_within_the_limits_is_read(fetch: RobotModel, tmp_path: Path) -> None:
    srdf = read_srdf(_with_state(tmp_path, "shoulder_lift_joint", "1.4"), fetch)
    assert [dict(s.values) for s in srdf.states] == [{"shoulder_lift_joint": 1.4}]


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "100"])
def test_a_value_not_finite_or_past_a_limit_is_refused(
    fetch: RobotModel, tmp_path: Path, value: str
) -> None:
    with pytest.raises(SrdfError) as caught:
        read_srdf(_with_state(tmp_path, "shoulder_lift_joint", value), fetch)
    message = str(caught.value)
    assert f"value {value!r} of joint 'shoulder_lift_joint'" in message
    assert "within its limits" in message and caught.value.line is not None


def test_a_blank_value_is_an_srdf_error(fetch: RobotModel, tmp_path: Path) -> None:
    with pytest.raises(SrdfError, match=r"joint 'shoulder_lift_joint' has a blank value"):
        read_srdf(_with_state(tmp_path, "shoulder_lift_joint", " "), fetch)

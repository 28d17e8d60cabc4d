"""Drafting with an SRDF (the Fetch's MoveIt configuration) and with package paths.

The Fetch's SRDF names its arm group and gripper and 134 disabled collision pairs, but no
named state: the tests add a ``tuck`` state (the values of fetch_teleop's ``tuck_arm.py``)
and a ``home`` state to a copy, to see the preferred one picked as parking.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from robocram.cli import main
from robocram.robot_check import check_robot
from robocram.robots import (
    DraftDescription,
    MissingMeshWarning,
    RobotDescription,
    SrdfError,
    draft_description,
    load_description,
)
from robocram.robots.description import DEFAULT_ALLOWED_CONTACTS
from robocram.robots.robot_model import RobotModel
from robocram.robots.self_contacts import SelfContacts
from robocram.robots.srdf import read_srdf

from .conftest import TINY_URDF

FETCH = Path(__file__).resolve().parents[1] / "data" / "fetch"
FETCH_URDF = FETCH / "fetch_description" / "robots" / "fetch.urdf"
FETCH_SRDF = FETCH / "fetch_moveit_config" / "config" / "fetch.srdf"
ARM = (
    "shoulder_pan_joint",
    "shoulder_lift_joint",
    "upperarm_roll_joint",
    "elbow_flex_joint",
    "forearm_roll_joint",
    "wrist_flex_joint",
    "wrist_roll_joint",
)
TUCK = (1.32, 1.40, -0.2, 1.72, 0.0, 1.66, 0.0)  # [rad] fetch_teleop/scripts/tuck_arm.py


def _state(name: str, group: str, values: dict[str, float]) -> str:
    joints = "".join(f'<joint name="{j}" value="{v}"/>' for j, v in values.items())
    return f'<group_state name="{name}" group="{group}">{joints}</group_state>'


def _srdf_with(tmp_path: Path, extra: str, old: str = "", new: str = "") -> Path:
    """A copy of the Fetch's SRDF with ``extra`` elements added and ``old`` replaced."""
    text = FETCH_SRDF.read_text(encoding="utf-8").replace("</robot>", extra + "</robot>")
    path = tmp_path / "fetch.srdf"
    path.write_text(text.replace(old, new) if old else text, encoding="utf-8")
    return path


def _draft(urdf: Path, srdf: Path | None = None, **kwargs: object) -> DraftDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)  # the Fetch's meshes are left out
        return draft_description(urdf, srdf=srdf, **kwargs)  # type: ignore[arg-type]


@pytest.fixture
def tucked_srdf(tmp_path: Path) -> Path:
    """The Fetch's SRDF with "home" (zeros, on the arm) and "tuck" (with the torso)."""
    home = _state("home", "arm", dict.fromkeys(ARM, 0.0))
    values = {"torso_lift_joint": 0.05, **dict(zip(ARM, TUCK, strict=True))}
    tuck = _state("tuck", "arm_with_torso", values)
    return _srdf_with(tmp_path, home + tuck)


def test_srdf_parks_the_arm_at_its_preferred_named_state(tucked_srdf: Path) -> None:
    draft = _draft(FETCH_URDF, tucked_srdf)
    arm = draft.description.arms["arm"]
    assert arm.joints == ARM  # group "arm", not "arm_with_torso": the torso is drafted apart
    assert arm.base_link == "torso_lift_link"
    assert dict(arm.parking) == pytest.approx(dict(zip(ARM, TUCK, strict=True)))  # tuck before home
    assert "named state 'tuck'" in draft.why["arms.arm.parking"]
    assert "arms.arm.parking" not in draft.doubts
    assert draft.description.torso_joint == "torso_lift_joint"


def test_srdf_disabled_pairs_become_allowed_contacts(tucked_srdf: Path) -> None:
    contacts = _draft(FETCH_URDF, tucked_srdf).description.allowed_contacts
    assert contacts[:2] == DEFAULT_ALLOWED_CONTACTS
    assert len(contacts) == 2 + 134
    for pair in [("base_link", "bellows_link"), ("elbow_flex_link", "gripper_link")]:
        assert pair in contacts
    assert ("base_link", "gripper_link") not in contacts


def test_srdf_draft_runs_and_loads(tucked_srdf: Path, tmp_path: Path) -> None:
    draft = _draft(FETCH_URDF, tucked_srdf)
    text = draft.source(tmp_path / "fetch.py")
    assert "*DEFAULT_ALLOWED_CONTACTS" in text
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        (tmp_path / "fetch.py").write_text(text, encoding="utf-8")
        loaded = load_description(str(tmp_path / "fetch.py"))  # a robot file, as users load it
    assert loaded.arms["arm"].joints == ARM
    assert loaded.arms["arm"].parking["elbow_flex_joint"] == pytest.approx(1.72)
    assert ("bellows_link", "torso_lift_link") in loaded.allowed_contacts


def test_srdf_draft_checks_as_the_plain_draft_does(tucked_srdf: Path) -> None:
    """Every check passes, as for the plain draft: the boxes standing in for the hand's
    meshes are sized from its joints (issue 37; from the inertia, the palm's reached 5 cm
    past the fingers' base and the grip closed on nothing)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(_draft(FETCH_URDF, tucked_srdf).description)
    assert card.passed, card.render()
    assert "arm arm: parking" in [r.name for r in card.results]


def test_srdf_without_named_states_keeps_the_drafted_parking() -> None:
    plain, srdf = _draft(FETCH_URDF), _draft(FETCH_URDF, FETCH_SRDF)
    assert srdf.description.arms["arm"].parking == plain.description.arms["arm"].parking
    assert "no state named stow" in srdf.doubts["arms.arm.parking"]


@pytest.mark.filterwarnings("ignore::robocram.robots.MissingMeshWarning")
def test_the_fetchs_own_srdf_has_no_named_state_so_it_parks_stowed() -> None:
    """fetch_moveit_config's SRDF: groups, an end effector and 134 disabled pairs, but no
    ``group_state``; the disabled pairs become allowed contacts, parking the stowed pose."""
    assert "group_state" not in FETCH_SRDF.read_text(encoding="utf-8")
    draft = _draft(FETCH_URDF, FETCH_SRDF)
    desc = draft.description
    semantics = read_srdf(
        FETCH_SRDF, RobotModel.from_file(FETCH_URDF, missing_packages_as_boxes=True)
    )
    assert semantics.states == ()
    assert len(semantics.disabled_pairs) == 134
    assert desc.allowed_contacts == DEFAULT_ALLOWED_CONTACTS + semantics.disabled_pairs
    parking = dict(desc.arms["arm"].parking)
    assert set(parking) == set(ARM)
    assert draft.why["arms.arm.parking"].startswith("stowed: within limits")
    model = load_description(desc).model
    assert not SelfContacts(model).touches(parking)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        card = check_robot(desc)
    assert card.passed, card.render()  # its boxed hand sized from the joints (issue 37)


def test_srdf_state_named_like_stow_wins_over_tuck(tmp_path: Path) -> None:
    stow = _state("arm_stowed", "arm", dict.fromkeys(ARM, 0.1))
    tuck = _state("tuck", "arm", dict(zip(ARM, TUCK, strict=True)))
    draft = _draft(FETCH_URDF, _srdf_with(tmp_path, tuck + stow))
    assert dict(draft.description.arms["arm"].parking) == pytest.approx(dict.fromkeys(ARM, 0.1))


def test_srdf_naming_an_unknown_link_says_which_and_how_to_fix(tmp_path: Path) -> None:
    bad = _srdf_with(tmp_path, "", 'link2="bellows_link2"', 'link2="bellow_link2"')
    with pytest.raises(SrdfError) as info:
        _draft(FETCH_URDF, bad)
    message = str(info.value)
    assert "<disable_collisions>" in message and "'bellow_link2'" in message
    assert "did you mean 'bellows_link2'" in message
    assert info.value.line == 40  # its first disable_collisions naming bellows_link2


def test_malformed_srdf_is_an_srdf_error(tmp_path: Path) -> None:
    bad = tmp_path / "bad.srdf"
    bad.write_text('<robot name="fetch"><group name="arm">\n</robot>', encoding="utf-8")
    with pytest.raises(SrdfError, match="not well-formed XML") as info:
        _draft(FETCH_URDF, bad)
    assert info.value.line == 2


def test_srdf_unknown_elements_are_ignored(tmp_path: Path) -> None:
    draft = _draft(FETCH_URDF, _srdf_with(tmp_path, '<passive_joint name="x"/><whatever/>'))
    assert draft.description.arms["arm"].joints == ARM


def test_cli_draft_takes_an_srdf(
    tucked_srdf: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "fetch.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        code = main(["robot", "draft", str(FETCH_URDF), "--srdf", str(tucked_srdf), "-o", str(out)])
    assert code == 0
    assert '"wrist_flex_joint": 1.66' in out.read_text(encoding="utf-8")


def test_missing_package_gives_boxes_and_a_warning(tmp_path: Path) -> None:
    urdf = tmp_path / "alone" / "tiny.urdf"
    urdf.parent.mkdir()
    urdf.write_text(TINY_URDF, encoding="utf-8")
    with pytest.warns(MissingMeshWarning, match="'tiny_pkg' not found.*--package-path") as caught:
        draft = draft_description(urdf)
    assert len(caught) == 1
    assert draft.description.name == "tiny"


def test_package_path_resolves_the_package(tiny_package: Path, tmp_path: Path) -> None:
    urdf = tmp_path / "alone" / "tiny.urdf"
    urdf.parent.mkdir()
    urdf.write_text(TINY_URDF, encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("error", MissingMeshWarning)
        draft = draft_description(urdf, package_paths=[tmp_path / "nothing", tiny_package])
    assert draft.description.name == "tiny"


def test_cli_check_passes_package_paths(
    tmp_path: Path, tiny_package: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    seen: list[RobotDescription] = []

    def check(desc: RobotDescription) -> object:
        seen.append(desc)
        raise SystemExit(0)

    monkeypatch.setattr("robocram.robot_check.check_robot", check)
    with pytest.raises(SystemExit):
        main(["robot", "check", "pr2", "--package-path", str(tiny_package), "--package-path", "x"])
    assert seen[0].package_paths[-2:] == (tiny_package, Path("x"))

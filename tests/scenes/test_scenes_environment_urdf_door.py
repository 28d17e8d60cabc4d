"""An environment's URDF passes the robots' URDF door before it is drafted (issue 42, bad 2)."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.cli import main
from robocram.command_exit import EXIT_INPUT
from robocram.robots import UrdfError
from robocram.scenes import draft_environment
from robocram.world import TooManyLinksError
from robocram.world.robot_urdf import MAX_LINKS

LINK = '<link name="{0}"><collision><geometry><box size="1 1 0.1"/></geometry></collision></link>'
JOINT = '<joint name="{0}" type="fixed"><parent link="{1}"/><child link="{2}"/></joint>'


def looped_urdf(folder: Path) -> Path:
    """``shelf`` hangs from ``floor`` and from ``board``, which hangs from ``shelf``."""
    parts = [LINK.format(n) for n in ("floor", "shelf", "board")]
    parts += [
        JOINT.format("floor_to_shelf", "floor", "shelf"),
        JOINT.format("shelf_to_board", "shelf", "board"),
        JOINT.format("board_to_shelf", "board", "shelf"),
    ]
    path = folder / "looped.urdf"
    path.write_text(f'<robot name="looped">{"".join(parts)}</robot>', "utf-8")
    return path


def test_a_link_with_two_parents_is_refused_naming_it(tmp_path: Path) -> None:
    with pytest.raises(UrdfError, match=r"link 'shelf' is the child of joints") as caught:
        draft_environment(looped_urdf(tmp_path))
    assert "'floor_to_shelf'" in str(caught.value) and "must be a tree" in str(caught.value)


def test_env_draft_refuses_the_loop_on_the_command_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "looped.py"
    assert main(["env", "draft", str(looped_urdf(tmp_path)), "-o", str(out)]) == EXIT_INPUT
    assert "link 'shelf' is the child of joints" in capsys.readouterr().err
    assert not out.exists()


def test_a_joint_with_an_undefined_link_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "dangling.urdf"
    body = LINK.format("floor") + JOINT.format("floor_to_shelf", "floor", "shelf")
    path.write_text(f'<robot name="dangling">{body}</robot>', "utf-8")
    with pytest.raises(UrdfError, match=r"joint 'floor_to_shelf' has child link 'shelf'"):
        draft_environment(path)


def test_more_links_than_pybullet_holds_are_refused_before_drafting(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Boards that slide (no fixed joint to cut the model at): not even parts would fit."""
    count = MAX_LINKS + 1
    slide = JOINT.replace('type="fixed">', 'type="prismatic"><axis xyz="1 0 0"/>'
                          '<limit lower="0" upper="0.1" velocity="1" effort="1"/>')  # fmt: skip
    parts = [LINK.format(f"board_{i}") for i in range(count + 1)]
    parts += [slide.format(f"joint_{i}", "board_0", f"board_{i}") for i in range(1, count + 1)]
    path = tmp_path / "shelves.urdf"
    path.write_text(f'<robot name="shelves">{"".join(parts)}</robot>', "utf-8")
    with pytest.raises(TooManyLinksError, match=rf"{count} links .* at most {MAX_LINKS}"):
        draft_environment(path)
    assert main(["env", "draft", str(path), "-o", str(tmp_path / "shelves.py")]) == EXIT_INPUT
    assert f"PyBullet holds at most {MAX_LINKS}" in capsys.readouterr().err

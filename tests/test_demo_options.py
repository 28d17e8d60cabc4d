"""``make demo ROBOT=file DEMO_ARGS=...``: retries from the command line (issue 37, item 5)."""

from __future__ import annotations

import pytest

from robocram.demo import Retries, command_line


@pytest.mark.parametrize("bad", ["0", "-2", "many"])
def test_a_retry_count_that_is_no_count_is_refused_naming_it(
    bad: str, capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as stop:
        command_line(["--robot", "pr2", "--stand-retries", bad])
    assert stop.value.code == 2
    assert f"{bad!r} is no count; give a whole number >= 1" in capsys.readouterr().err


def test_retries_given_become_the_transporting_designators_keys() -> None:
    assert Retries().keys() == {}
    assert Retries(10).keys() == {"stand_retries": 10}
    assert Retries(10, 4).keys() == {"stand_retries": 10, "place_retries": 4}

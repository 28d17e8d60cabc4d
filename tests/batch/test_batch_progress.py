"""The batch progress bar: off when the output is no terminal, counting variants when on."""

from __future__ import annotations

import io
import os

import pytest

from robocram.batch import Variant, project_variants
from robocram.batch.progress import ProgressBar


def test_off_when_stdout_is_not_a_terminal(capsys: pytest.CaptureFixture[str]) -> None:
    run = project_variants([Variant("a"), Variant("b")], workers=1)  # stdout is captured
    assert not run.progress.shown
    run.cancel()
    assert capsys.readouterr().out == ""


def test_on_for_a_terminal() -> None:
    main, side = os.openpty()
    with os.fdopen(side, "w") as terminal:
        bar = ProgressBar(5, None, terminal)
        assert bar.shown
        bar.close()
        assert not ProgressBar(5, False, terminal).shown
    os.close(main)


def test_forced_on_counts_the_variants() -> None:
    stream = io.StringIO()
    variants = [
        Variant("ok"),
        Variant("toaster", parameters={"object_type": "toaster"}),
        Variant("typo", parameters={"objec": "mug"}),
    ]
    run = project_variants(variants, workers=1, progress=True, progress_stream=stream)
    results = run.collect()
    assert [r.succeeded for r in results] == [True, False, False]
    text = stream.getvalue()
    assert "3/3" in text and "failed=2" in text and "lost=0" in text
    assert (run.progress.failed, run.progress.lost) == (2, 0)

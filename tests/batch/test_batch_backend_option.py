"""``robocram batch --backend`` is checked by the batch package, which loads only for it.

The command line no longer imports the batch package to list the backends (issue 27, item
4), so an unknown backend is a bad option (exit 3) that names the ones there are.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.cli import EXIT_INPUT, main

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "batch_tabletop.yaml"


def test_an_unknown_backend_exits_3_naming_the_backends(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["batch", str(EXAMPLE), "--backend", "dask"]) == EXIT_INPUT
    err = capsys.readouterr().err
    assert "dask" in err and "processes" in err and "ray" in err

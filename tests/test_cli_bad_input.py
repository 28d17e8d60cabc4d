"""Bad command-line input exits 3 with a message naming the fix (issue 24, item 4).

Before: ``--port 70000``, ``--port -1`` and a ``--host`` not of this machine gave raw
tracebacks (exit 1), and a binary batch spec a raw ``UnicodeDecodeError`` (exit 1).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.cli import EXIT_INPUT, main


@pytest.mark.parametrize("port", ["70000", "-1"])
def test_a_port_out_of_range_exits_3(
    port: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["replay", str(tmp_path / "runs.db"), "--port", port]) == EXIT_INPUT
    assert f"--port {port} is out of range; give a port in 1..65535" in capsys.readouterr().err


def test_a_host_that_is_not_ours_exits_3(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # 192.0.2.1 is TEST-NET-1 (RFC 5737): never an address of this machine
    assert main(["replay", str(tmp_path / "runs.db"), "--host", "192.0.2.1"]) == EXIT_INPUT
    err = capsys.readouterr().err
    assert "--host 192.0.2.1 is not an address of this machine" in err
    assert "use 127.0.0.1 (this machine only) or 0.0.0.0" in err


def test_a_binary_batch_spec_exits_3(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    spec = tmp_path / "spec.yaml"
    spec.write_bytes(b"variants: 3\n\xff\xd8\xff\xe0 a JPEG in disguise")
    assert main(["batch", str(spec)]) == EXIT_INPUT
    err = capsys.readouterr().err
    assert "not UTF-8 text (byte 0xff at offset 12)" in err
    assert "saved as UTF-8" in err

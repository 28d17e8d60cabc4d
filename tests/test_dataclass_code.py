"""Dataclasses' generated methods come from the disk table as ``exec`` would compile them.

Each process runs in a fresh interpreter with its own cache folder; what it compiled and
what it read is told by the table itself and checked against Python's own ``compile``.
"""

from __future__ import annotations

import dataclasses
import json
import marshal
import os
import subprocess
import sys
from pathlib import Path

from robocram.dataclass_code import CodeTable

SRC = Path(__file__).resolve().parents[1] / "src"
_SPOT = (
    "import dataclasses\n"
    "@dataclasses.dataclass(frozen=True, order=True)\n"
    "class Spot:\n"
    "    x: float\n"
    "    name: str = 'a'\n"
)
_PROBE = """
import dataclasses, json, sys, types, robocram
table = dataclasses.exec.__self__
added = table._added  # robocram's own classes, compiled at its import
@dataclasses.dataclass
class Users:  # a user's class (module __main__): compiled by exec itself, never kept
    x: float
assert table._added == added and not any("Users" in s for s in table._kept or {})
ours = types.ModuleType("robocram.probe_spot")  # a robocram module's class: kept
sys.modules[ours.__name__] = ours
exec(SPOT, ours.__dict__)
Spot = ours.Spot
s = Spot(1.0)
try:
    s.x = 2.0
    frozen = False
except dataclasses.FrozenInstanceError:
    frozen = True
print(json.dumps([repr(s), s == Spot(1.0), Spot(0.5) < s, frozen, table._added]))
"""


def _run(cache: Path) -> list[object]:
    """What the probe prints, run in a fresh interpreter with ``cache`` as its cache."""
    env = {**os.environ, "ROBOCRAM_CACHE_DIR": str(cache), "PYTHONPATH": str(SRC)}
    done = subprocess.run(
        [sys.executable, "-c", f"SPOT = {_SPOT!r}\n{_PROBE}"],
        capture_output=True,
        text=True,
        check=True,
        env=env,
    )
    found: list[object] = json.loads(done.stdout.strip().splitlines()[-1])
    return found


def _table_file(cache: Path) -> Path:
    (path,) = (cache / "dataclass-code").glob("*.code")
    return path


def test_a_second_process_compiles_nothing_and_builds_the_same_class(tmp_path: Path) -> None:
    first = _run(tmp_path)
    assert first == ["Spot(x=1.0, name='a')", True, True, True, True]  # compiled, then kept
    kept = marshal.loads(_table_file(tmp_path).read_bytes()[32:])
    init = next(
        source for source in kept if "def __init__(self,x:_type_x,name:_type_name" in source
    )
    assert kept[init] == compile(init, "<string>", "exec", dont_inherit=True)
    assert _run(tmp_path) == [*first[:4], False]  # all read from the table


def test_a_damaged_table_is_compiled_again_and_replaced(tmp_path: Path) -> None:
    _run(tmp_path)
    path = _table_file(tmp_path)
    data = bytearray(path.read_bytes())
    data[len(data) // 2] ^= 0xFF
    path.write_bytes(bytes(data))
    assert _run(tmp_path)[-1] is True  # nothing trusted: compiled again
    assert _run(tmp_path)[-1] is False  # the rewritten table is whole


def test_the_table_s_exec_runs_code_objects_and_keeps_no_future_flags(tmp_path: Path) -> None:
    table = CodeTable(tmp_path / "t.code")
    space: dict[str, object] = {}
    ours = {"__name__": "robocram.probe"}  # a robocram module's globals: kept
    table.exec("def f(x: int) -> int:\n    return x + 1\n", ours, space)
    table.exec("def g() -> int:\n    return 2\n", {"__name__": "__main__"}, space)
    assert space["g"]() == 2  # type: ignore[operator]
    f = space["f"]
    assert callable(f) and f(1) == 2
    assert f.__annotations__ == {"x": int, "return": int}  # not strings: no __future__
    table.exec(compile("y = 3", "<string>", "exec"), {}, space)
    assert space["y"] == 3
    table.save()
    assert CodeTable(tmp_path / "t.code").code("def f(x: int) -> int:\n    return x + 1\n")
    kept = marshal.loads((tmp_path / "t.code").read_bytes()[32:])
    assert list(kept) == ["def f(x: int) -> int:\n    return x + 1\n"]  # not a user's g
    assert dataclasses.exec.__self__.__class__ is CodeTable  # type: ignore[attr-defined]

"""How much of the code says ``typing.Any``: counted by tools/any_count.py, limits only fall."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

TOOL = Path(__file__).resolve().parents[1] / "tools" / "any_count.py"
OUTSIDE_LOGIC = 203  # issue 22 asks for at most 220; lower this as uses go, never raise it
LOGIC = 7


def _tool() -> ModuleType:
    spec = importlib.util.spec_from_file_location("any_count", TOOL)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_any_stays_within_its_limits() -> None:
    found = _tool().counts()
    outside = sum(n for package, n in found.items() if package != "logic")
    print(f"typing.Any: {outside} outside logic (limit {OUTSIDE_LOGIC}), {found['logic']} in logic")
    assert outside <= OUTSIDE_LOGIC, sorted(found.items(), key=lambda item: -item[1])
    assert found["logic"] <= LOGIC


def test_the_counter_sees_every_spelling(tmp_path: Path) -> None:
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "a.py").write_text(
        "from typing import Any, cast\nimport typing\n"
        "Alias = dict[str, Any]\n"
        "def f(x: Any, *a: 'list[Any]') -> typing.Any:\n"
        "    '''Any in a docstring is not counted.'''\n"
        "    return cast(Any, x)  # nor Any in a comment\n",
        encoding="utf-8",
    )
    (package / "b.py").write_text("def g(x: object) -> object:\n    return x\n", encoding="utf-8")
    assert _tool().counts(tmp_path) == {"pkg": 5}

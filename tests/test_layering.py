"""Layers import downwards only (docs/architecture.md): checked on the source text, and
the doc's layer table checked against the rules here."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "robocram"

# package -> the robocram packages it may import
ALLOWED: dict[str, set[str]] = {
    "logic": set(),
    "tf": set(),
    "knowledge": {"logic", "tf"},
    "designators": {"logic", "tf"},
    "robots": {"knowledge", "logic", "tf"},
    "execution": {"designators", "logic", "tf"},
    "world": {"robots", "knowledge", "logic", "tf"},
    "kinematics": {"robots", "logic", "tf"},
    "scenes": {"world", "kinematics", "robots", "logic", "tf"},
    "grasping": {"world", "kinematics", "robots", "knowledge", "logic", "tf"},
    "costmaps": {
        "grasping",
        "world",
        "kinematics",
        "designators",
        "robots",
        "knowledge",
        "logic",
        "tf",
    },
    "motion": {"world", "kinematics", "execution", "robots", "logic", "tf"},
    "projection": {
        "motion",
        "grasping",
        "costmaps",
        "world",
        "kinematics",
        "execution",
        "designators",
        "robots",
        "logic",
        "tf",
    },
    "turtlesim": {"execution", "designators", "logic", "tf"},
    "plans": {"execution", "designators", "knowledge", "logic", "tf"},
    "traces": {"motion", "costmaps", "world", "execution", "designators", "robots", "logic", "tf"},
    "viewer": {
        "traces",
        "motion",
        "costmaps",
        "world",
        "execution",
        "designators",
        "robots",
        "logic",
        "tf",
    },
    "ros": {
        "motion",
        "grasping",
        "costmaps",
        "scenes",
        "world",
        "kinematics",
        "execution",
        "designators",
        "robots",
        "logic",
        "tf",
    },
    "ros_driver": {
        "ros",
        "projection",
        "motion",
        "scenes",
        "world",
        "execution",
        "designators",
        "robots",
        "tf",
    },
    "batch": {
        "traces",
        "motion",
        "scenes",
        "plans",
        "projection",
        "world",
        "execution",
        "designators",
        "robots",
        "tf",
    },
    "robot_check": {
        "projection",
        "motion",
        "world",
        "kinematics",
        "execution",
        "designators",
        "robots",
        "tf",
    },
}


def _imported_packages(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: set[str] = set()
    for node in ast.walk(tree):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module]
        for name in names:
            parts = name.split(".")
            if parts[0] == "robocram" and len(parts) > 1:
                found.add(parts[1])
    return found


def _layer_files() -> list[tuple[str, Path]]:
    return [
        (package, path)
        for package in ALLOWED
        if (SRC / package).is_dir()
        for path in sorted((SRC / package).rglob("*.py"))
    ]


@pytest.mark.parametrize(("package", "path"), _layer_files(), ids=lambda v: str(v))
def test_imports_point_down(package: str, path: Path) -> None:
    used = _imported_packages(path) - {package}
    upward = used - ALLOWED[package]
    assert not upward, (
        f"{path.relative_to(SRC)} imports {sorted(upward)}: "
        f"layer {package!r} may use {sorted(ALLOWED[package])}"
    )


def test_every_package_has_a_layer() -> None:
    packages = {p.name for p in SRC.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    assert packages <= set(ALLOWED), f"add {sorted(packages - set(ALLOWED))} to ALLOWED"


def test_logic_uses_stdlib_only() -> None:
    for path in (SRC / "logic").rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import | ast.ImportFrom):
                mod = node.names[0].name if isinstance(node, ast.Import) else (node.module or "")
                assert mod.split(".")[0] not in {"numpy", "pybullet", "pinocchio"}, path


# Import cycles between modules of one package that are not fixed yet, with their owner.
# Each entry is the set of modules in one cycle (a strongly connected component).
KNOWN_CYCLES: list[frozenset[str]] = []


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imported_modules(path: Path, module: str, known: set[str]) -> set[str]:
    """Every robocram module `path` imports anywhere: top level, in functions, for typing."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parent = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(parent + ([base] if base else []))
            for alias in node.names:  # `from pkg import submodule` imports the submodule
                sub = f"{base}.{alias.name}"
                found.add(sub if sub in known else base)
    return found & known


def _cycles_inside_packages() -> list[frozenset[str]]:
    """Strongly connected components (size > 1) of the import graph within each package."""
    paths = {_module_name(p): p for p in SRC.rglob("*.py")}
    known = set(paths)
    graph = {
        m: {d for d in _imported_modules(p, m, known) if d.split(".")[:2] == m.split(".")[:2]} - {m}
        for m, p in paths.items()
    }
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    cycles: list[frozenset[str]] = []

    def visit(v: str) -> None:  # Tarjan's algorithm; the graph is a few hundred modules
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = set()
            while True:
                w = stack.pop()
                component.add(w)
                if w == v:
                    break
            if len(component) > 1:
                cycles.append(frozenset(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return cycles


def test_no_import_cycles_between_modules_of_a_package() -> None:
    new = [sorted(c) for c in _cycles_inside_packages() if c not in KNOWN_CYCLES]
    assert not new, (
        f"modules import each other (counting imports inside functions and for typing): {new};"
        " break the cycle with a typing.Protocol in the lower module or move the shared part"
        " into a module both import"
    )


def test_known_cycles_still_exist() -> None:
    """A fixed cycle must leave KNOWN_CYCLES, so the list never hides a new one."""
    found = _cycles_inside_packages()
    stale = [sorted(c) for c in KNOWN_CYCLES if c not in found]
    assert not stale, f"remove these fixed cycles from KNOWN_CYCLES: {stale}"


def test_cycle_finder_sees_function_level_imports(tmp_path: Path) -> None:
    a = tmp_path / "a.py"
    a.write_text("def f():\n    from robocram.logic import b\n", encoding="utf-8")
    assert _imported_modules(a, "robocram.logic.a", {"robocram.logic.b"}) == {"robocram.logic.b"}


# docs/architecture.md's layer table says what ALLOWED enforces, in the same order.
DOC = SRC.parents[1] / "docs" / "architecture.md"
ROW = re.compile(r"^\| `robocram\.(\w+)` \| (.+) \| (.+) \|$")
NOTES = {"stdlib only", "numpy"}  # what a layer with no robocram import may write instead


def _table(text: str) -> list[tuple[str, list[str]]]:
    """The rows of the layer table: package, then the items of its "may import" cell."""
    return [
        (m[1], [item.strip() for item in m[3].split(",")])
        for m in map(ROW.match, text.splitlines())
        if m
    ]


def test_the_doc_lists_the_layers_in_the_tests_order() -> None:
    assert [package for package, _ in _table(DOC.read_text(encoding="utf-8"))] == list(ALLOWED)


def test_each_layer_may_import_what_the_test_allows() -> None:
    for package, items in _table(DOC.read_text(encoding="utf-8")):
        named = {item for item in items if item not in NOTES}
        assert named == ALLOWED[package], (
            f"docs/architecture.md, {package}: the doc says {sorted(named)}, "
            f"tests/test_layering.py allows {sorted(ALLOWED[package])}"
        )


def test_the_table_is_lowest_first() -> None:
    above: set[str] = set()
    for package, items in _table(DOC.read_text(encoding="utf-8")):
        assert {item for item in items if item not in NOTES} <= above, package
        above.add(package)


def test_the_reader_sees_a_drifted_row() -> None:
    text = (
        "| `robocram.logic` | engine | stdlib only |\n"
        "| `robocram.viewer` | viewer | traces and everything below |\n"
    )
    assert _table(text) == [("logic", ["stdlib only"]), ("viewer", ["traces and everything below"])]

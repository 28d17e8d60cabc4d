"""Layers import downwards only (docs/architecture.md): checked on the source text."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "robocram"

# package -> the robocram packages it may import
ALLOWED: dict[str, set[str]] = {
    "logic": set(),
    "tf": set(),
    "designators": {"logic", "tf"},
    "robots": {"logic", "tf"},
    "execution": {"designators", "logic", "tf"},
    "world": {"robots", "logic", "tf"},
    "kinematics": {"robots", "tf"},
    "projection": {"world", "kinematics", "execution", "designators", "robots", "logic", "tf"},
    "turtlesim": {"execution", "designators", "logic", "tf"},
    "plans": {"execution", "designators", "logic", "tf"},
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

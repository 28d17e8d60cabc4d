"""World is the only door to PyBullet, and its helpers respect other classes' privacy.

Checked on the source text: nothing outside ``robocram.world`` imports ``pybullet`` or
``pybullet_data``; only the :class:`World` facade, the base of its parts and its snapshots
name the world's tables (:class:`WorldTables`), so the parts reach them only through the
tables given them, and nothing else at all; no module in ``world`` (nor in ``scenes``, the
demo or the examples) reads or writes an underscored attribute of an object other than
``self``/``cls`` (so a part uses the tables' and PyBullet's public API only); the facade
keeps at most 25 public methods; the demo and the examples import only the names packages
export in ``__all__``.
"""

from __future__ import annotations

import ast
import importlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src" / "robocram"
BACKEND = {"pybullet", "pybullet_data", "pybullet_utils", "pybullet_envs"}
PRIVATE_CHECKED = [
    *sorted((SRC / "world").rglob("*.py")),
    *sorted((SRC / "scenes").rglob("*.py")),
    SRC / "projection" / "collision_mode.py",
    SRC / "projection" / "gripper.py",
]
PUBLIC_USERS = [SRC / "demo.py", *sorted((ROOT / "examples").glob("*.py"))]


def _tree(path: Path) -> ast.Module:
    return ast.parse(path.read_text(encoding="utf-8"))


def _imported_modules(tree: ast.Module) -> list[str]:
    found: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found.append(node.module)
    return found


def _outside_world() -> list[Path]:
    return [p for p in sorted(SRC.rglob("*.py")) if "world" not in p.relative_to(SRC).parts[:1]]


@pytest.mark.parametrize("path", _outside_world(), ids=lambda p: str(p.relative_to(SRC)))
def test_only_world_imports_pybullet(path: Path) -> None:
    backend = [m for m in _imported_modules(_tree(path)) if m.split(".")[0] in BACKEND]
    assert not backend, (
        f"{path.relative_to(SRC)} imports {backend}: only robocram.world may talk to "
        "PyBullet; add a public World method instead"
    )


TABLE_HOLDERS = {"world.py", "world_part.py", "world_state.py", "world_tables.py"}
WORLD_PUBLIC_METHODS_MAX = 25  # issue 39; the rest lives in the parts


def _names_tables(tree: ast.Module) -> bool:
    """Whether a module imports :class:`WorldTables` (at any level, typing too)."""
    return any(
        isinstance(node, ast.ImportFrom)
        and (node.module or "").endswith("world_tables")
        and any(a.name == "WorldTables" for a in node.names)
        for node in ast.walk(tree)
    )


def _is_part(tree: ast.Module) -> bool:
    return any(
        isinstance(node, ast.ClassDef)
        and any(isinstance(b, ast.Name) and b.id == "WorldPart" for b in node.bases)
        for node in ast.walk(tree)
    )


@pytest.mark.parametrize("path", sorted(SRC.rglob("*.py")), ids=lambda p: str(p.relative_to(SRC)))
def test_only_the_facade_and_its_parts_hold_the_tables(path: Path) -> None:
    tree = _tree(path)
    in_world = path.parent == SRC / "world"
    allowed = in_world and (path.name in TABLE_HOLDERS or _is_part(tree))
    assert allowed or not _names_tables(tree), (
        f"{path.relative_to(SRC)} names WorldTables: only World, its parts and its "
        "snapshots hold the tables; ask the world (or the right part) instead"
    )


def test_the_facade_stays_small() -> None:
    from robocram.world import World

    public = [n for n in vars(World) if not n.startswith("_") and _callable_or_property(World, n)]
    assert len(public) <= WORLD_PUBLIC_METHODS_MAX, (
        f"World has {len(public)} public methods ({sorted(public)}); put the new one in a part"
    )


def _callable_or_property(cls: type, name: str) -> bool:
    value = vars(cls)[name]
    return callable(value) or isinstance(value, property)


def _foreign_private(tree: ast.Module) -> list[str]:
    """``x._name`` uses where ``x`` is not ``self`` or ``cls`` (dunders allowed)."""
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Attribute):
            continue
        name = node.attr
        if not name.startswith("_") or (name.startswith("__") and name.endswith("__")):
            continue
        owner = node.value
        if isinstance(owner, ast.Name) and owner.id in {"self", "cls"}:
            continue
        found.append(f"line {node.lineno}: .{name}")
    return found


@pytest.mark.parametrize("path", PRIVATE_CHECKED, ids=lambda p: str(p.relative_to(SRC)))
def test_no_private_attribute_of_another_object(path: Path) -> None:
    used = _foreign_private(_tree(path))
    assert not used, f"{path.relative_to(SRC)} reaches into private attributes: {used}"


def test_the_private_check_sees_a_reach_in() -> None:
    tree = ast.parse("def f(world):\n    return world._attachments, self._ok, w.__class__")
    assert _foreign_private(tree) == ["line 2: ._attachments"]


@pytest.mark.parametrize("path", PUBLIC_USERS, ids=lambda p: p.name)
def test_demo_and_examples_import_only_public_names(path: Path) -> None:
    for node in ast.walk(_tree(path)):
        if not (isinstance(node, ast.ImportFrom) and (node.module or "").startswith("robocram")):
            continue
        module = importlib.import_module(node.module or "")
        exported = set(getattr(module, "__all__", ()))
        assert node.module.count(".") == 1, f"{path.name}: {node.module} is not a package"
        missing = [a.name for a in node.names if a.name not in exported]
        assert not missing, f"{path.name} imports {missing} from {node.module}, not in __all__"

"""Count the uses of ``typing.Any`` in robocram's source, per package.

What is counted: every reference to ``typing.Any`` in the code of ``src/robocram/**.py``
(the name ``Any`` imported from ``typing``, or ``typing.Any``) wherever it stands: in an
annotation, a type alias, a ``cast`` or a generic's arguments. The import line itself,
comments, docstrings and other strings are not. Quoted annotations are parsed and counted
too. An alias of ``Any`` counts once, where it is defined; its uses count as the alias.

Usage: python tools/any_count.py [--src DIR]
"""

from __future__ import annotations

import argparse
import ast
from collections import Counter
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "robocram"


def _any_names(tree: ast.Module) -> tuple[set[str], set[str]]:
    """Names bound to ``typing.Any`` and names bound to the ``typing`` module."""
    anys: set[str] = set()
    modules: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module == "typing":
            anys.update(a.asname or a.name for a in node.names if a.name == "Any")
        elif isinstance(node, ast.Import):
            modules.update(a.asname or a.name for a in node.names if a.name == "typing")
    return anys, modules


def _is_any(node: ast.AST, anys: set[str], modules: set[str]) -> bool:
    """Whether ``node`` names ``typing.Any`` (as ``Any`` or as ``typing.Any``)."""
    if isinstance(node, ast.Name):
        return node.id in anys
    return (
        isinstance(node, ast.Attribute)
        and node.attr == "Any"
        and isinstance(node.value, ast.Name)
        and node.value.id in modules
    )


def _count_in(node: ast.AST, anys: set[str], modules: set[str]) -> int:
    return sum(_is_any(inner, anys, modules) for inner in ast.walk(node))


def _quoted_annotations(tree: ast.Module) -> list[ast.AST]:
    """Annotations written as strings, parsed."""
    found: list[ast.AST] = []
    for node in ast.walk(tree):
        notes: list[ast.expr | None] = []
        if isinstance(node, ast.arg):
            notes = [node.annotation]
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            notes = [node.returns]
        elif isinstance(node, ast.AnnAssign):
            notes = [node.annotation]
        for note in notes:
            for part in ast.walk(note) if note is not None else ():
                if isinstance(part, ast.Constant) and isinstance(part.value, str):
                    try:
                        found.append(ast.parse(part.value, mode="eval"))
                    except SyntaxError:
                        continue
    return found


def any_uses(path: Path) -> int:
    """How many times the module at ``path`` refers to ``typing.Any``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    anys, modules = _any_names(tree)
    if not anys and not modules:
        return 0
    body = [n for n in tree.body if not (isinstance(n, ast.ImportFrom) and n.module == "typing")]
    count = sum(_count_in(n, anys, modules) for n in body)
    return count + sum(_count_in(n, anys, modules) for n in _quoted_annotations(tree))


def counts(src: Path = SRC) -> Counter[str]:
    """Uses of ``typing.Any`` per package of ``src`` (top-level modules under their name)."""
    found: Counter[str] = Counter()
    for path in sorted(src.rglob("*.py")):
        package = path.relative_to(src).parts[0].removesuffix(".py")
        found[package] += any_uses(path)
    return found


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--src", type=Path, default=SRC)
    args = parser.parse_args()
    found = counts(args.src)
    outside = sum(n for package, n in found.items() if package != "logic")
    for package, n in sorted(found.items(), key=lambda item: (-item[1], item[0])):
        if n and package != "logic":
            print(f"{package:<16}{n:>6}")
    print(f"{'logic':<16}{found['logic']:>6}")
    print(f"{'outside logic':<16}{outside:>6}")
    print(f"{'total':<16}{sum(found.values()):>6}")


if __name__ == "__main__":
    main()

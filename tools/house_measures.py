"""The measures issue 39 ("a house to live in") asks to report before and after, read from
the source with Python's own parser, so that each step of the redesign can show its
effect in the same terms.

- ``perform`` definitions (goal 1);
- functions with a ``robot: str`` parameter, and those also taking ``world`` (goal 0
  outside the public edges: scenes, the command line, ``simulated_robot``); a robot's
  name kept as a label (in an error, a trajectory record, a KB query's atom) is a
  ``robot_name: str`` parameter, counted apart, and such a function must not look the
  robot up from it (``robot_name lookups``, goal 0);
- public methods of the ``World`` facade (goal <= 25; its tables, ``WorldTables``, are
  reached only by the world and its parts);
- caches kept by hand: bounded caches that evict by hand (``popitem(last=False)``,
  ``del d[next(iter(d))]``, ``d.pop(next(iter(d)))``; goal 0, the one bounded store,
  ``logic/lru.py``, which ``world.Derived`` keeps its values in, aside), state reads
  compared as a cache's validity
  (``body_state(...)`` outside the world's tables), functions decorated with ``functools``
  caches, ``derived(...)`` stores (a world's, declared with ``Derived``, apart from a
  robot model's, which depend on nothing but the model), ``Derived`` declarations, and
  module-level dictionaries written inside functions and module-level cache objects
  (goal 0 keeping world or model state): those that keep none are named in
  :data:`STATELESS_MEMOS`, each with why, and counted apart;
- bare built-in raises (``ValueError``, ``RuntimeError``, ``TypeError``, ``KeyError``)
  in library code (goal <= 10).

Usage: python tools/house_measures.py [--list]   (--list names every hit)
"""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterator
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "robocram"
# Where a robot's name comes in from outside and is looked up once: scenes, the command line,
# ``simulated_robot``, the demos, a batch's specs (the worker builds its scene from them) and
# the Prolog door of the grasp predicates (a query's robot arrives as an atom).
EDGES = (
    "scenes/",
    "cli.py",
    "_commands.py",
    "projection/simulated_robot.py",
    "demo.py",
    "batch/project_variants.py",
    "batch/worker.py",
    "grasping/grasp_predicates.py",
)
# Calls that find a robot from its name: a function given only a name as a label must not
# make them (its name says so: ``robot_name``).
LOOKUPS = {"robot", "object", "of", "robot_description", "load_description", "description"}
BARE = {"ValueError", "RuntimeError", "TypeError", "KeyError"}
CACHES = {"cache", "lru_cache", "cached_property"}
# Module-level memos that keep no world or model state, and why (``file name`` -> reason).
STATELESS_MEMOS = {
    "logic/goal_writer.py _FACTORIES": "code: Python compiled from generated clause source, "
    "keyed by that source text",
    "motion/configuration_checker.py _KINDS": "code: whether a checker class implements a "
    "protocol, keyed by the classes",
    "robots/robot_model.py MODELS": "weak: shares a parsed model between equal loads only "
    "while something else holds it",
}


def _modules() -> Iterator[tuple[str, ast.Module]]:
    for path in sorted(SRC.rglob("*.py")):
        yield str(path.relative_to(SRC)), ast.parse(path.read_text(encoding="utf-8"))


def _functions(tree: ast.AST) -> Iterator[ast.FunctionDef | ast.AsyncFunctionDef]:
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node


def _takes_robot_name(fn: ast.FunctionDef | ast.AsyncFunctionDef) -> tuple[bool, bool]:
    args = [*fn.args.posonlyargs, *fn.args.args, *fn.args.kwonlyargs]
    names = {a.arg for a in args}
    robot = any(
        a.arg == "robot" and a.annotation is not None and ast.unparse(a.annotation) == "str"
        for a in args
    )
    return robot, robot and "world" in names


def _name_lookups(fn: ast.FunctionDef | ast.AsyncFunctionDef) -> list[int]:
    """Lines where ``fn``, given a ``robot_name``, finds the robot from it."""
    args = [*fn.args.posonlyargs, *fn.args.args, *fn.args.kwonlyargs]
    if not any(a.arg == "robot_name" for a in args):
        return []
    return [
        node.lineno
        for node in ast.walk(fn)
        if isinstance(node, ast.Call)
        and _decorator_name(node) in LOOKUPS
        and any(
            isinstance(v, ast.Name) and v.id == "robot_name"
            for v in [*node.args, *(k.value for k in node.keywords)]
        )
    ]


def _takes_name_label(fn: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    args = [*fn.args.posonlyargs, *fn.args.args, *fn.args.kwonlyargs]
    return any(
        a.arg == "robot_name" and a.annotation is not None and ast.unparse(a.annotation) == "str"
        for a in args
    )


def _decorator_name(node: ast.expr) -> str:
    target = node.func if isinstance(node, ast.Call) else node
    return target.attr if isinstance(target, ast.Attribute) else getattr(target, "id", "")


def _module_dicts(tree: ast.Module) -> set[str]:
    names = set()
    for node in tree.body:
        value = node.value if isinstance(node, (ast.Assign, ast.AnnAssign)) else None
        if isinstance(value, (ast.Dict, ast.Call)) and (
            isinstance(value, ast.Dict) or _decorator_name(value) in ("dict", "defaultdict")
        ):
            names |= _bound(node)
    return names


def _bound(node: ast.stmt) -> set[str]:
    """The plain names an assignment binds."""
    if isinstance(node, ast.Assign):
        targets = node.targets
    elif isinstance(node, ast.AnnAssign):
        targets = [node.target]
    else:
        return set()
    return {t.id for t in targets if isinstance(t, ast.Name)}


def _cache_objects(tree: ast.Module) -> set[str]:
    """Module-level names bound to a cache object (a class named ``*Cache``, ``*Memo``,
    a weak dictionary)."""
    names = set()
    for node in tree.body:
        value = node.value if isinstance(node, (ast.Assign, ast.AnnAssign)) else None
        if isinstance(value, ast.Call) and any(
            word in _decorator_name(value) for word in ("Cache", "Memo", "Dictionary")
        ):
            names |= _bound(node)
    return names


def _written_in_functions(tree: ast.Module, names: set[str]) -> set[str]:
    written = set()
    for fn in _functions(tree):
        for node in ast.walk(fn):
            if (
                isinstance(node, ast.Subscript)
                and isinstance(node.ctx, ast.Store)
                and isinstance(node.value, ast.Name)
                and node.value.id in names
            ):
                written.add(node.value.id)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                base = node.func.value
                if isinstance(base, ast.Name) and base.id in names and node.func.attr in (
                    "setdefault", "update", "__setitem__",
                ):  # fmt: skip
                    written.add(base.id)
    return written


def _evicts_by_hand(node: ast.AST) -> bool:
    """Whether ``node`` drops a cache's oldest entry by hand."""
    if isinstance(node, ast.Delete):
        return any(isinstance(t, ast.Subscript) and _is_first_key(t.slice) for t in node.targets)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
        if node.func.attr == "popitem":
            return any(k.arg == "last" for k in node.keywords)
        return node.func.attr == "pop" and bool(node.args) and _is_first_key(node.args[0])
    return False


def _is_first_key(node: ast.expr) -> bool:
    """``next(iter(...))``: the oldest key of a dictionary."""
    return (
        isinstance(node, ast.Call)
        and _decorator_name(node) == "next"
        and bool(node.args)
        and isinstance(node.args[0], ast.Call)
        and _decorator_name(node.args[0]) == "iter"
    )


def _derived_kind(node: ast.Call) -> str:
    """Which store a ``derived(...)`` call uses: a robot model's or a world's."""
    receiver = ast.unparse(node.func.value) if isinstance(node.func, ast.Attribute) else ""
    return "model derived stores" if "model" in receiver else "world derived stores"


def measure() -> dict[str, list[str]]:
    """Per measure, the places that count (``file:line name``)."""
    found: dict[str, list[str]] = {
        "perform definitions": [],
        "robot: str parameters": [],
        "robot: str with world": [],
        "robot_name: str labels": [],
        "robot_name lookups": [],
        "World public methods": [],
        "hand-written caches": [],
        "state compares": [],
        "functools caches": [],
        "world derived stores": [],
        "model derived stores": [],
        "Derived declarations": [],
        "module-level memos": [],
        "stateless module memos": [],
        "bare built-in raises": [],
    }
    for name, tree in _modules():
        edge = name.startswith(EDGES[0]) or name.endswith(EDGES[1:])
        for fn in _functions(tree):
            where = f"{name}:{fn.lineno} {fn.name}"
            if fn.name == "perform":
                found["perform definitions"].append(where)
            robot, with_world = _takes_robot_name(fn)
            if robot and not edge:
                found["robot: str parameters"].append(where)
            if with_world and not edge:
                found["robot: str with world"].append(where)
            if _takes_name_label(fn):
                found["robot_name: str labels"].append(where)
            found["robot_name lookups"] += [
                f"{name}:{line} {fn.name}" for line in _name_lookups(fn)
            ]
            if any(_decorator_name(d) in CACHES for d in fn.decorator_list):
                found["functools caches"].append(where)
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef) and node.name == "World":
                for item in node.body:
                    if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)) and (
                        not item.name.startswith("_")
                    ):
                        found["World public methods"].append(f"{node.name}.{item.name}")
            if isinstance(node, ast.Call) and _decorator_name(node) == "derived":
                found[_derived_kind(node)].append(f"{name}:{node.lineno}")
            if isinstance(node, ast.Call) and _decorator_name(node) == "Derived":
                found["Derived declarations"].append(f"{name}:{node.lineno}")
            if _evicts_by_hand(node) and name != "logic/lru.py":
                found["hand-written caches"].append(f"{name}:{node.lineno}")
            if (
                isinstance(node, ast.Call)
                and _decorator_name(node) == "body_state"
                and name != "world/world_tables.py"
            ):
                found["state compares"].append(f"{name}:{node.lineno}")
            if (
                isinstance(node, ast.Raise)
                and node.exc is not None
                and (_decorator_name(node.exc) in BARE)
            ):
                found["bare built-in raises"].append(f"{name}:{node.lineno}")
        memos = _written_in_functions(tree, _module_dicts(tree)) | _cache_objects(tree)
        for memo in sorted(memos):
            where = f"{name} {memo}"
            why = STATELESS_MEMOS.get(where)
            if why is None:
                found["module-level memos"].append(where)
            else:
                found["stateless module memos"].append(f"{where} ({why})")
    return found


def main(argv: list[str]) -> None:
    for label, places in measure().items():
        print(f"{label:28s} {len(places):5d}")
        if "--list" in argv:
            for place in places:
                print(f"    {place}")


if __name__ == "__main__":
    main(sys.argv[1:])

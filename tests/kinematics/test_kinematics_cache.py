"""IK's caches live on objects their caller owns: bounded, gone with the model, no globals."""

from __future__ import annotations

import ast
import gc
import pickle
import weakref
from pathlib import Path

import pytest

from robocram.kinematics import IKOptions, IKSolver, KinematicsCache, PlanarBase, solve_ik
from robocram.kinematics.robot_kinematics import RobotKinematics, robot_kinematics
from robocram.logic.lru import LRUCache
from robocram.robots import load_description
from robocram.robots.robot_model import MODELS
from robocram.tf import Pose

CONTAINERS = {"dict", "list", "set", "OrderedDict", "WeakKeyDictionary", "WeakValueDictionary"}
KINEMATICS = Path(__file__).resolve().parents[2] / "src" / "robocram" / "kinematics"
TARGET = Pose((0.6, -0.2, 0.9))  # in front of the PR2's right arm


def _module_level_caches(path: Path) -> list[str]:
    """Module-level mutable containers and memoising decorators in ``path``."""
    found = []
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.Assign | ast.AnnAssign) and node.value is not None:
            if "__all__" in ast.unparse(node).split("=")[0]:
                continue
            value = node.value
            if isinstance(value, ast.Dict | ast.List | ast.Set) or (
                isinstance(value, ast.Call) and ast.unparse(value.func).split(".")[-1] in CONTAINERS
            ):
                found.append(f"{path.name}:{node.lineno}")
        if isinstance(node, ast.FunctionDef | ast.ClassDef):
            for inner in ast.walk(node):
                if isinstance(inner, ast.FunctionDef) and any(
                    "cache" in ast.unparse(d) for d in inner.decorator_list
                ):
                    found.append(f"{path.name}:{inner.lineno}")
    return found


def test_no_module_of_kinematics_keeps_a_cache() -> None:
    found = [hit for path in sorted(KINEMATICS.glob("*.py")) for hit in _module_level_caches(path)]
    assert found == []


def test_the_finder_sees_a_module_cache(tmp_path: Path) -> None:
    source = tmp_path / "m.py"
    source.write_text(
        "import functools, weakref\n_A: dict = {}\n_B = weakref.WeakKeyDictionary()\n"
        "@functools.lru_cache(maxsize=4)\ndef f(x): return x\n",
        encoding="utf-8",
    )
    assert _module_level_caches(source) == ["m.py:2", "m.py:3", "m.py:5"]


def test_the_bounded_store_drops_the_least_recently_used() -> None:
    kept: LRUCache[str, int] = LRUCache(2)
    kept.put("a", 1)
    kept.put("b", 2)
    assert kept.get("a") == 1  # now "b" is the least recently used
    kept.put("c", 3)
    assert (len(kept), kept.get("b"), kept.get("a"), kept.get("c")) == (2, None, 1, 3)
    builds = iter((4, 5))
    assert kept.get_or_build("d", lambda: next(builds)) == 4
    assert kept.get_or_build("d", lambda: next(builds)) == 4  # kept: not built again
    assert kept.get("a") is None  # "a" was the least recent
    with pytest.raises(ValueError, match="at least 1"):
        LRUCache(0)


def test_the_model_keeps_its_kinematics_and_its_cache() -> None:
    pr2 = load_description("pr2")
    assert robot_kinematics(pr2.model) is robot_kinematics(pr2.model)
    assert KinematicsCache.of(pr2.model) is KinematicsCache.of(pr2.model)
    solver = IKSolver.cached(pr2, "right")
    assert solver.cache is KinematicsCache.of(pr2.model)
    assert IKSolver.cached(pr2, "right") is solver
    again = load_description("pr2")  # the same file: the same model, and what it keeps
    assert again.model is pr2.model and IKSolver.cached(again, "right") is solver
    MODELS.clear()
    other = load_description("pr2")  # a new model starts with nothing kept
    assert other.model is not pr2.model
    assert KinematicsCache.of(other.model) is not solver.cache
    assert len(KinematicsCache.of(other.model).solvers) == 0


def test_what_a_model_keeps_goes_with_it() -> None:
    MODELS.clear()  # a model of its own: an earlier test's world may still hold the shared one
    pr2 = load_description("pr2")
    assert solve_ik(pr2, "right", TARGET).success
    model = weakref.ref(pr2.model)
    cache = weakref.ref(KinematicsCache.of(pr2.model))
    del pr2
    MODELS.clear()  # loads of one file share a model while the process keeps it
    gc.collect()
    assert (model(), cache()) == (None, None)


def test_a_callers_cache_is_bounded_and_shares_tables_between_equal_models() -> None:
    cache = KinematicsCache(solvers=2, tables=8)
    MODELS.clear()
    first = load_description("pr2")
    MODELS.clear()
    second = load_description("pr2")  # an equal model, not the same one
    assert second.model is not first.model
    right = IKSolver.cached(first, "right", cache=cache)
    assert IKSolver.cached(second, "right", cache=cache).table is right.table  # same geometry
    IKSolver.cached(first, "left", cache=cache)
    assert len(cache.solvers) == 2  # the first solver was dropped
    assert IKSolver.cached(first, "right", cache=cache) is not right
    assert len(KinematicsCache.of(first.model).solvers) == 0  # the model's own stayed empty


def test_answers_do_not_depend_on_the_cache() -> None:
    hsr = load_description("hsrb")
    target = Pose((0.9, 0.3, 0.7))
    answers = [
        solve_ik(
            hsr,
            "arm",
            target,
            options=IKOptions(use_torso=True, base=PlanarBase(), random_seed=3),
            cache=c,
        )
        for c in (None, KinematicsCache(), KinematicsCache(solvers=1, tables=1, planar_models=1))
    ]
    assert answers[0].success and answers[0].base_motion is not None
    for other in answers[1:]:
        assert other.joint_positions == answers[0].joint_positions  # bit for bit
        assert other.base_motion == answers[0].base_motion


def test_a_pickled_model_leaves_what_it_derived_behind() -> None:
    pr2 = load_description("pr2")
    kin = robot_kinematics(pr2.model)
    copy = pickle.loads(pickle.dumps(pr2.model))
    assert isinstance(robot_kinematics(copy), RobotKinematics)
    assert robot_kinematics(copy) is not kin
    assert copy.joints.keys() == pr2.model.joints.keys()

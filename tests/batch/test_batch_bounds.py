"""Batch specs are bounded: counts, seeds; variants are drawn as workers ask (issue 24).

Before: ``variants: 1000000000`` drew every variant up front (minutes, growing memory),
``seed: 2**70`` was taken and every variant then failed with numpy's raw error, and a
query's ``time_limit=nan`` meant no limit.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from robocram.batch import BadSpec, Variant
from robocram.batch.batch_spec import MAX_VARIANTS, load_spec
from robocram.batch.errors import BatchError
from robocram.batch.worker_pool import Pending
from robocram.logic import KnowledgeBase

PLACE = {"mug-1": {"x": [-0.05, 0.05], "yaw": [0.0, 1.0]}}


def _spec(tmp_path: Path, **data: object) -> Path:
    path = tmp_path / "spec.json"
    path.write_text(json.dumps({"place": PLACE, **data}), encoding="utf-8")
    return path


def test_a_count_above_the_bound_is_refused_naming_how_to_raise_it(tmp_path: Path) -> None:
    with pytest.raises(BadSpec, match=r"more than 100000 variants; .*`max_variants: 1000000000`"):
        load_spec(_spec(tmp_path, variants=1_000_000_000))
    assert MAX_VARIANTS == 100_000


def test_a_raised_bound_draws_lazily_the_same_variants(tmp_path: Path) -> None:
    big = load_spec(_spec(tmp_path, variants=10**9, max_variants=10**9, seed=5)).variants
    small = load_spec(_spec(tmp_path, variants=3, seed=5)).variants
    assert len(big) == 10**9
    assert big[:3] == tuple(small)
    assert [v.seed for v in big[:3]] == [5, 6, 7]


def test_workers_are_handed_drawn_variants_one_at_a_time(tmp_path: Path) -> None:
    drawn = load_spec(_spec(tmp_path, variants=10**9, max_variants=10**9)).variants
    pending = Pending(drawn)
    first, second = pending.popleft(), pending.popleft()
    assert (first[0], second[0], len(pending)) == (0, 1, 10**9 - 2)
    assert (first[1], second[1]) == tuple(drawn[:2])
    assert pending.names == {0: "v000", 1: "v001"}


def test_pending_refuses_what_is_not_a_variant() -> None:
    pending = Pending(["not a variant"])  # type: ignore[list-item]
    with pytest.raises(BatchError, match="'not a variant' is not a Variant"):
        pending.popleft()


@pytest.mark.parametrize("seed", [2**70, 2**32, -1])
def test_a_seed_outside_32_bits_is_refused(tmp_path: Path, seed: int) -> None:
    with pytest.raises(BadSpec, match=r"seed=.*give an integer in 0..4294967295"):
        load_spec(_spec(tmp_path, variants=2, seed=seed))
    with pytest.raises(BatchError, match=r"give an integer in 0..4294967295"):
        Variant("v", seed=seed)


def test_the_last_variants_seed_must_fit_too(tmp_path: Path) -> None:
    with pytest.raises(
        BadSpec, match=r"4294967295\+1 passes 4294967295; give a seed <= 4294967294"
    ):
        load_spec(_spec(tmp_path, variants=2, seed=2**32 - 1))
    assert [v.seed for v in load_spec(_spec(tmp_path, variants=2, seed=2**32 - 2)).variants] == [
        2**32 - 2,
        2**32 - 1,
    ]


@pytest.mark.parametrize("limit", [math.nan, math.inf, -1.0])
def test_a_time_limit_must_be_finite_and_not_negative(limit: float) -> None:
    with pytest.raises(ValueError, match=r"time_limit must be a finite number >= 0 \[s\]"):
        KnowledgeBase().query("true", time_limit=limit)

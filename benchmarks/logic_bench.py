"""Benchmark robocram.logic against SWI-Prolog on the same programs, in one run.

Prints naive reverse of 30 elements (LIPS), 8-queens all solutions (s), a first-argument
lookup in 100,000 facts (µs per query) and a million-deep recursion (s, peak MiB), with
our/SWI ratios when `swipl` is installed (benchmarks/setup_swipl.sh installs it). Times
are CPU seconds on both sides (SWI's statistics(cputime)), so a loaded machine skews less.
Usage: python benchmarks/logic_bench.py [--nrev-runs N] [--depth N]
"""

from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import tempfile
import time
import tracemalloc
from pathlib import Path

from robocram.logic import KnowledgeBase

PROGRAM = """
app([], L, L).
app([H|T], L, [H|R]) :- app(T, L, R).
nrev([], []).
nrev([H|T], R) :- nrev(T, RT), app(RT, [H], R).
nrev_loop(0) :- !.
nrev_loop(K) :-
    nrev([1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24,25,26,27,28,29,30], _),
    K1 is K - 1, nrev_loop(K1).
queens(N, Qs) :- numlist(1, N, Ns), permutation_(Ns, Qs), safe(Qs).
permutation_([], []).
permutation_(L, [H|T]) :- select(H, L, R), permutation_(R, T).
safe([]).
safe([Q|Qs]) :- no_attack(Q, Qs, 1), safe(Qs).
no_attack(_, [], _).
no_attack(Q, [Q1|Qs], D) :- Q =\\= Q1 + D, Q =\\= Q1 - D, D1 is D + 1, no_attack(Q, Qs, D1).
count(0).
count(N) :- N > 0, M is N - 1, count(M).
lookup_loop(0) :- !.
lookup_loop(K) :- Key is (K * 7919) mod 100000, fact(Key, _), K1 is K - 1, lookup_loop(K1).
"""
FACTS = "\n".join(f"fact({i}, v{i})." for i in range(100_000))
NREV_LI = 496
LOOKUPS = 20_000


def ours(nrev_runs: int, depth: int) -> dict[str, float]:
    kb = KnowledgeBase()
    kb.consult(PROGRAM)
    kb.consult(FACTS, group="facts")
    res: dict[str, float] = {}
    t = time.process_time()
    kb.holds("nrev_loop(N)", N=nrev_runs)
    res["nrev_lips"] = nrev_runs * NREV_LI / (time.process_time() - t)
    t = time.process_time()
    n = kb.first("findall(Q, queens(8, Q), L), length(L, N)")["N"]  # type: ignore[index]
    res["queens_s"] = time.process_time() - t
    assert n == 92, n
    t = time.process_time()
    kb.holds("lookup_loop(N)", N=LOOKUPS)
    res["lookup_us"] = (time.process_time() - t) / LOOKUPS * 1e6
    t = time.process_time()
    kb.holds("count(N)", N=depth)
    res["deep_s"] = time.process_time() - t
    tracemalloc.start()
    kb.holds("count(N)", N=depth)
    res["deep_mib"] = tracemalloc.get_traced_memory()[1] / 2**20
    tracemalloc.stop()
    return res


def swi(nrev_runs: int, depth: int) -> dict[str, float] | None:
    if shutil.which("swipl") is None:
        return None
    driver = f"""
:- initialization(main, main).
time_goal(G, T) :-
    statistics(cputime, T0), (call(G) -> true ; true), statistics(cputime, T1), T is T1 - T0.
main :-
    time_goal(nrev_loop({nrev_runs}), T1),
    L is {nrev_runs} * {NREV_LI} / max(T1, 1.0e-9),
    format("nrev_lips ~w~n", [L]),
    time_goal((findall(Q, queens(8, Q), Qs), length(Qs, 92)), T2),
    format("queens_s ~w~n", [T2]),
    time_goal(lookup_loop({LOOKUPS}), T3), U is T3 / {LOOKUPS} * 1.0e6,
    format("lookup_us ~w~n", [U]),
    time_goal(count({depth}), T4), format("deep_s ~w~n", [T4]),
    statistics(globalused, G), statistics(localused, Lo), M is (G + Lo) / 1048576,
    format("deep_mib ~w~n", [M]).
"""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench.pl"
        path.write_text(PROGRAM + FACTS + "\n" + driver)
        out = subprocess.run(
            ["swipl", str(path)], capture_output=True, text=True, timeout=600
        ).stdout
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"(\w+) ([\d.e+-]+)", out)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--nrev-runs", type=int, default=300)
    parser.add_argument("--depth", type=int, default=1_000_000)
    args = parser.parse_args()
    subprocess.run(["sh", str(Path(__file__).with_name("setup_swipl.sh"))], check=False)
    mine = ours(args.nrev_runs, args.depth)
    ref = swi(args.nrev_runs * 100, args.depth)
    print(f"{'benchmark':<28}{'robocram':>14}{'SWI-Prolog':>14}{'ours/SWI':>12}")
    rows = [
        ("nrev30 [LIPS]", "nrev_lips"),
        ("8-queens all [s]", "queens_s"),
        ("100k-fact lookup [us/query]", "lookup_us"),
        (f"count({args.depth}) [s]", "deep_s"),
        ("count peak memory [MiB]", "deep_mib"),
    ]
    for label, key in rows:
        theirs = ref.get(key) if ref else None
        ratio = f"{mine[key] / theirs:>12.4g}" if theirs else f"{'n/a':>12}"
        theirs_text = f"{theirs:>14.4g}" if theirs is not None else f"{'(no swipl)':>14}"
        print(f"{label:<28}{mine[key]:>14.4g}{theirs_text}{ratio}")


if __name__ == "__main__":
    main()

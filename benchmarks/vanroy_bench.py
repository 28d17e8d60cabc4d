"""The classic van Roy benchmark programs on robocram.logic and on `swipl -O`, in one run.

The programs tak, nrev, queens_8, qsort, deriv, primes, zebra, mu, serialise and crypt are
written here from their well-known descriptions. The others live in benchmarks/vanroy/:
boyer, browse and poly_10 are written for robocram from the published descriptions
(boyer with our own, smaller lemma table); query (public domain) and chat_parser (MIT)
are fetched unchanged from github.com/SWI-Prolog/bench, each file's header says so.
Each runs in a failure-driven loop; the script prints seconds per iteration (CPU time)
for both systems, their ratio and the geometric mean of the ratios.
Usage: python benchmarks/vanroy_bench.py [--scale S] [--only NAME ...]
"""

from __future__ import annotations

import argparse
import math
import re
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

from robocram.logic import KnowledgeBase, fast_queries

PROGRAMS: dict[str, tuple[str, str, int]] = {}  # name -> (program, goal, iterations)

PROGRAMS["tak"] = (
    """
tak(X, Y, Z, A) :- X =< Y, !, Z = A.
tak(X, Y, Z, A) :-
    X1 is X - 1, Y1 is Y - 1, Z1 is Z - 1,
    tak(X1, Y, Z, A1), tak(Y1, Z, X, A2), tak(Z1, X, Y, A3), tak(A1, A2, A3, A).
""",
    "tak(18, 12, 6, _)",
    1,
)
PROGRAMS["nrev"] = (
    """
app([], L, L).
app([H|T], L, [H|R]) :- app(T, L, R).
nrev([], []).
nrev([H|T], R) :- nrev(T, RT), app(RT, [H], R).
""",
    "nrev([1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24,25,26,27,28,29,30], _)",
    200,
)
PROGRAMS["queens_8"] = (
    """
q_range(N, N, [N]) :- !.
q_range(M, N, [M|Ns]) :- M1 is M + 1, q_range(M1, N, Ns).
q_sel(X, [X|T], T).
q_sel(X, [H|T], [H|R]) :- q_sel(X, T, R).
q_perm([], []).
q_perm(L, [H|T]) :- q_sel(H, L, R), q_perm(R, T).
q_safe([]).
q_safe([Q|Qs]) :- q_noattack(Q, Qs, 1), q_safe(Qs).
q_noattack(_, [], _).
q_noattack(Q, [Q1|Qs], D) :- Q =\\= Q1 + D, Q =\\= Q1 - D, D1 is D + 1, q_noattack(Q, Qs, D1).
queens(N, Qs) :- q_range(1, N, Ns), q_perm(Ns, Qs), q_safe(Qs).
""",
    "queens(8, _)",
    2,
)
PROGRAMS["qsort"] = (
    """
qsort([X|L], R, R0) :- qpart(L, X, L1, L2), qsort(L2, R1, R0), qsort(L1, R, [X|R1]).
qsort([], R, R).
qpart([X|L], Y, [X|L1], L2) :- X =< Y, !, qpart(L, Y, L1, L2).
qpart([X|L], Y, L1, [X|L2]) :- qpart(L, Y, L1, L2).
qpart([], _, [], []).
""",
    "qsort([27,74,17,33,94,18,46,83,65,2,32,53,28,85,99,47,28,82,6,11,55,29,39,81,90,37,10,"
    "0,66,51,7,21,85,27,31,63,75,4,95,99,11,28,61,74,18,92,40,53,59,8], _, [])",
    100,
)
PROGRAMS["deriv"] = (
    """
d(U+V, X, DU+DV) :- !, d(U, X, DU), d(V, X, DV).
d(U-V, X, DU-DV) :- !, d(U, X, DU), d(V, X, DV).
d(U*V, X, DU*V+U*DV) :- !, d(U, X, DU), d(V, X, DV).
d(U/V, X, (DU*V-U*DV)/(V^2)) :- !, d(U, X, DU), d(V, X, DV).
d(U^N, X, DU*N*(U^N1)) :- !, integer(N), N1 is N - 1, d(U, X, DU).
d(-U, X, -DU) :- !, d(U, X, DU).
d(exp(U), X, exp(U)*DU) :- !, d(U, X, DU).
d(log(U), X, DU/U) :- !, d(U, X, DU).
d(X, X, 1) :- !.
d(_, _, 0).
deriv :-
    d((x+1)*((x^2+2)*(x^3+3)), x, _),
    d(((((((((x/x)/x)/x)/x)/x)/x)/x)/x)/x, x, _),
    d(log(log(log(log(log(log(log(log(log(log(x)))))))))), x, _),
    d(((((((((x*x)*x)*x)*x)*x)*x)*x)*x)*x, x, _).
""",
    "deriv",
    500,
)
PROGRAMS["primes"] = (
    """
p_ints(L, H, [L|R]) :- L =< H, !, M is L + 1, p_ints(M, H, R).
p_ints(_, _, []).
p_sift([], []).
p_sift([I|Is], [I|Ps]) :- p_remove(I, Is, New), p_sift(New, Ps).
p_remove(_, [], []).
p_remove(P, [I|Is], Nis) :- 0 is I mod P, !, p_remove(P, Is, Nis).
p_remove(P, [I|Is], [I|Nis]) :- p_remove(P, Is, Nis).
primes(Limit, Ps) :- p_ints(2, Limit, Is), p_sift(Is, Ps).
""",
    "primes(98, _)",
    100,
)
PROGRAMS["zebra"] = (
    """
z_right(A, B, [B, A|_]).
z_right(A, B, [_|Y]) :- z_right(A, B, Y).
z_next(A, B, [A, B|_]).
z_next(A, B, [B, A|_]).
z_next(A, B, [_|Y]) :- z_next(A, B, Y).
z_mem(X, [X|_]).
z_mem(X, [_|Y]) :- z_mem(X, Y).
zebra(Owner) :-
    Hs = [h(_, norwegian, _, _, _), _, h(_, _, _, milk, _), _, _],
    z_mem(h(red, english, _, _, _), Hs),
    z_mem(h(_, spanish, dog, _, _), Hs),
    z_mem(h(green, _, _, coffee, _), Hs),
    z_mem(h(_, ukrainian, _, tea, _), Hs),
    z_right(h(green, _, _, _, _), h(ivory, _, _, _, _), Hs),
    z_mem(h(_, _, snails, _, winstons), Hs),
    z_mem(h(yellow, _, _, _, kools), Hs),
    z_next(h(_, _, _, _, chesterfields), h(_, _, fox, _, _), Hs),
    z_next(h(_, _, _, _, kools), h(_, _, horse, _, _), Hs),
    z_mem(h(_, _, _, orange_juice, lucky_strikes), Hs),
    z_mem(h(_, japanese, _, _, parliaments), Hs),
    z_next(h(_, norwegian, _, _, _), h(blue, _, _, _, _), Hs),
    z_mem(h(_, Owner, zebra, _, _), Hs).
""",
    "zebra(japanese)",
    5,
)
PROGRAMS["mu"] = (
    """
mu_app([], L, L).
mu_app([H|T], L, [H|R]) :- mu_app(T, L, R).
theorem([m, i], _, [[a, m, i]]).
theorem(R, Depth, [[N|R]|P]) :- Depth > 0, D is Depth - 1, theorem(S, D, P), mu_rule(N, S, R).
mu_rule(1, S, R) :- mu_r1(S, R).
mu_rule(2, S, R) :- mu_r2(S, R).
mu_rule(3, S, R) :- mu_r3(S, R).
mu_rule(4, S, R) :- mu_r4(S, R).
mu_r1([i], [i, u]).
mu_r1([H|X], [H|Y]) :- mu_r1(X, Y).
mu_r2([m|X], [m|Y]) :- mu_app(X, X, Y).
mu_r3([i, i, i|X], [u|X]).
mu_r3([H|X], [H|Y]) :- mu_r3(X, Y).
mu_r4([u, u|X], X).
mu_r4([H|X], [H|Y]) :- mu_r4(X, Y).
""",
    "theorem([m, u, i, i, u], 5, _)",
    20,
)
PROGRAMS["serialise"] = (
    """
serialise(L, R) :- s_pairs(L, R, A), s_arrange(A, T), s_number(T, 1, _).
s_pairs([X|L], [Y|R], [pair(X, Y)|A]) :- s_pairs(L, R, A).
s_pairs([], [], []).
s_arrange([X|L], tree(T1, X, T2)) :- s_split(L, X, L1, L2), s_arrange(L1, T1), s_arrange(L2, T2).
s_arrange([], void).
s_split([X|L], X, L1, L2) :- !, s_split(L, X, L1, L2).
s_split([X|L], Y, [X|L1], L2) :- s_before(X, Y), !, s_split(L, Y, L1, L2).
s_split([X|L], Y, L1, [X|L2]) :- s_before(Y, X), !, s_split(L, Y, L1, L2).
s_split([], _, [], []).
s_before(pair(X1, _), pair(X2, _)) :- X1 < X2.
s_number(tree(T1, pair(_, N1), T2), N0, N) :-
    s_number(T1, N0, N1), N2 is N1 + 1, s_number(T2, N2, N).
s_number(void, N, N).
serialise_test :- atom_codes('ABLE WAS I ERE I SAW ELBA', L), serialise(L, _).
""",
    "serialise_test",
    200,
)
PROGRAMS["crypt"] = (
    """
c_digit(D) :- c_sel(D, [0,1,2,3,4,5,6,7,8,9], _).
c_sel(X, [X|T], T).
c_sel(X, [H|T], [H|R]) :- c_sel(X, T, R).
% SEND + MORE = MONEY, all letters distinct, S and M not zero.
crypt([S,E,N,D,M,O,R,Y]) :-
    Ds0 = [0,1,2,3,4,5,6,7,8,9],
    c_sel(S, Ds0, Ds1), S > 0, c_sel(E, Ds1, Ds2), c_sel(N, Ds2, Ds3), c_sel(D, Ds3, Ds4),
    c_sel(M, Ds4, Ds5), M =:= 1, c_sel(O, Ds5, Ds6), c_sel(R, Ds6, Ds7), c_sel(Y, Ds7, _),
    1000*S + 100*E + 10*N + D + 1000*M + 100*O + 10*R + E =:=
        10000*M + 1000*O + 100*N + 10*E + Y.
""",
    "crypt(_)",
    1,
)

VANROY = Path(__file__).with_name("vanroy")
FILE_RUNS = {"boyer": 5, "browse": 1, "chat_parser": 2, "poly_10": 5, "query": 20}
for _name, _runs in FILE_RUNS.items():
    PROGRAMS[_name] = ((VANROY / f"{_name}.pl").read_text(encoding="utf-8"), "top", _runs)

LOOP = "bench_loop(G, N) :- between(1, N, _), call(G), fail.\nbench_loop(_, _).\n"


def ours(name: str, scale: float) -> float:
    """Seconds per iteration of program `name` on robocram.logic."""
    program, goal, n = PROGRAMS[name]
    runs = max(1, round(n * scale))
    kb = KnowledgeBase()
    kb.consult(program + LOOP)
    kb.holds(f"bench_loop(({goal}), 2)")  # warm: generated code, indexes
    if not kb.holds(goal):
        raise RuntimeError(f"{name}: {goal} failed on robocram")
    with fast_queries():  # paced young-generation collection, as a host would opt in
        t = time.process_time()  # CPU seconds, as SWI's statistics(cputime): fair under load
        kb.holds(f"bench_loop(({goal}), {runs})")
        return (time.process_time() - t) / runs


def swi(names: list[str], scale: float) -> dict[str, float]:
    """Seconds per iteration of each program on `swipl -O` (empty without swipl)."""
    if shutil.which("swipl") is None:
        return {}
    out: dict[str, float] = {}
    for name in names:
        program, goal, n = PROGRAMS[name]
        runs = max(1, round(n * scale * 200))
        driver = f"""
:- initialization(main, main).
main :- ( \\+ ({goal}) -> format("failed~n") ; true ),
    statistics(cputime, T0), bench_loop(({goal}), {runs}), statistics(cputime, T1),
    T is (T1 - T0) / {runs}, format("secs ~w~n", [T]).
"""
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / f"{name}.pl"
            path.write_text(program + LOOP + driver)
            result = subprocess.run(
                ["swipl", "-O", str(path)], capture_output=True, text=True, timeout=900
            )
        found = re.search(r"secs ([\d.e+-]+)", result.stdout)
        if found:
            out[name] = float(found.group(1))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--scale", type=float, default=1.0, help="multiply iteration counts")
    parser.add_argument("--only", nargs="*", default=list(PROGRAMS), choices=list(PROGRAMS))
    args = parser.parse_args()
    subprocess.run(["sh", str(Path(__file__).with_name("setup_swipl.sh"))], check=False)
    theirs = swi(args.only, args.scale)
    print(f"{'program':<12}{'robocram [s]':>14}{'swipl -O [s]':>14}{'ours/SWI':>10}")
    ratios: list[float] = []
    for name in args.only:
        mine = ours(name, args.scale)
        ref = theirs.get(name)
        ratio = mine / ref if ref else None
        if ratio is not None:
            ratios.append(ratio)
        ref_text = f"{ref:>14.3e}" if ref is not None else f"{'n/a':>14}"
        ratio_text = f"{ratio:>10.1f}" if ratio is not None else f"{'n/a':>10}"
        print(f"{name:<12}{mine:>14.3e}{ref_text}{ratio_text}")
    if ratios:
        geo = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        print(f"{'geomean':<12}{'':>14}{'':>14}{geo:>10.1f}")


if __name__ == "__main__":
    main()

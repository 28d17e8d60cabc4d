"""The van Roy programs, unmodified from SWI-Prolog's benchmark suite: robocram vs `swipl -O`.

Sixteen programs of github.com/SWI-Prolog/bench (commit bba99e6), each run through its
own `top/0`, byte for byte as published (checked by SHA-256 below). That repository has
no licence file: the seven programs whose headers grant redistribution (six public
domain, chat_parser under MIT) are stored in benchmarks/vanroy/ unchanged; the other nine
(boyer, browse, crypt, mu, poly_10, queens_8, sendmore, tak, zebra) carry no notice, so
they are read from a copy of that repository given with --bench (a checkout or a bare
git directory; `git clone https://github.com/SWI-Prolog/bench`), never stored here.

Each engine runs each program in its own process, in a failure-driven loop of `top`
calibrated to at least --seconds of CPU time (per engine: robocram runs far fewer
iterations than SWI). Rounds interleave the engines program by program; the table shows
CPU seconds per iteration, the minimum over --rounds rounds, the per-program ratio, the
geometric mean over all sixteen and the worst ratio, with the load average.
Usage: python benchmarks/vanroy_bench.py [--bench DIR] [--rounds 3] [--seconds 1] [--only ...]
"""

from __future__ import annotations

import argparse
import hashlib
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

COMMIT = "bba99e69975d2066b42928dd38b57c20a4a3f142"
SHA256 = {
    "boyer": "0c9ef09e838ce22fcb98217a77e544c45a5421d0b23ce1fb3ef2f3bba8cd679f",
    "browse": "efa4f77c9a64738b3a4ce1a81322da99bb98f07378935e78af3f71a746abe62a",
    "chat_parser": "8e6b7015496b61419f0a53901c9664ef65e672989faf6191bb64e8ef7b6d88f9",
    "crypt": "e1bb586f07a407c87d4b6fc44a8d364005263bc1d8a9fe3ed06f542d38eb6446",
    "derive": "cd7b577b2c94fb5c876e179ac5c1b9a9b27677885f334a56cfbc0ab9b9d1a405",
    "mu": "88a73bacd55df9d36fe0bf61e9d5dcdde741276b47e3b1abe250241a44fd16b0",
    "nreverse": "1e3a79d7048550c8b6d31e1a30c49c4de3aef1bf1e8c647295f5b4e2d831d0ad",
    "poly_10": "bb0b4165bf7a50ee19f607b235ea3123b2d79630b00507064b7e39bc54607bca",
    "qsort": "0b9d0562f75391fdf6cf840bb7aadbbb50a7b4970aad11fdd361d66e0c38f777",
    "queens_8": "fbe3dce5861470ec8b5ac404b924be9e6c57536487151485b915545eacac4ae8",
    "query": "cc74ba6df223b00ecb15ac38c2b8da048eca028375d4c35619a867402c925ed1",
    "sendmore": "85c8ac63ac0b9b9e998d5155fca55b097a5406b5b0bbba3507112bf4eff44755",
    "serialise": "2d8ae71e502d6ed2908ca721e8717b4b7951e062ec1efa79deced8a1fceba496",
    "sieve": "cdedb4eae9ad8df2c07283e7af48f9252b1b9eb075769f73a30127db11baa08f",
    "tak": "8de0f5fcf054fe4c84b8eec6b32db5c57c7654b27bec4ddd0fdfced403724ca3",
    "zebra": "a31800d327a41d924a91ff7e1767d885635e22957459dd65a9959e2ada1ecb06",
}
STORED = Path(__file__).with_name("vanroy")
# The same driver on both engines: one iteration is `top` run to its first answer.
LOOP = "bench_loop(N) :- between(1, N, _), \\+ \\+ top, fail.\nbench_loop(_).\n"
SWI_MAIN = """
:- initialization(main, main).
bench_time(N, T) :- statistics(cputime, T0), bench_loop(N), statistics(cputime, T1),
    T is T1 - T0.
calibrate(N, S, Nf, Tf) :- bench_time(N, T),
    (   T >= S -> Nf = N, Tf = T
    ;   T < S / 20 -> N1 is N * 10, calibrate(N1, S, Nf, Tf)
    ;   N1 is ceiling(N * S * 1.05 / T), calibrate(N1, S, Nf, Tf)
    ).
main :- ( \\+ top -> format("failed~n") ; true ),
    calibrate(1, {seconds}, N, T), format("iterations ~w cpu ~w~n", [N, T]).
"""
_RESULT = re.compile(r"iterations (\d+) cpu ([\d.e+-]+)")


def program_text(name: str, bench: Path | None) -> str | None:
    """The published text of program `name`, checked; None when it is not at hand."""
    stored = STORED / f"{name}.pl"
    if stored.exists():
        data = stored.read_bytes()
    elif bench is None:
        return None
    elif (bench / "programs").is_dir():
        data = (bench / "programs" / f"{name}.pl").read_bytes()
    else:  # a bare git directory
        data = subprocess.run(
            ["git", f"--git-dir={bench}", "show", f"{COMMIT}:programs/{name}.pl"],
            capture_output=True,
            check=True,
        ).stdout
    if hashlib.sha256(data).hexdigest() != SHA256[name]:
        raise RuntimeError(f"{name}.pl differs from SWI-Prolog/bench at {COMMIT[:7]}")
    return data.decode("utf-8")


def worker(path: Path, seconds: float) -> None:
    """Run one program on robocram in this process; print iterations and CPU seconds."""
    from robocram.logic import KnowledgeBase, fast_queries

    kb = KnowledgeBase()
    kb.consult(path.read_text(encoding="utf-8") + LOOP)
    if not kb.holds("top"):
        print("failed")
    n = 1
    while True:
        with fast_queries():  # paced young-generation collection, as a host opts in
            t0 = time.process_time()
            kb.holds(f"bench_loop({n})")
            took = time.process_time() - t0
        if took >= seconds:
            print(f"iterations {n} cpu {took}")
            return
        n = n * 10 if took < seconds / 20 else math.ceil(n * seconds * 1.05 / took)


def run_once(engine: str, path: Path, seconds: float) -> tuple[int, float]:
    """(iterations, CPU seconds) of one calibrated run of `path` on `engine`."""
    if engine == "robocram":
        cmd = [sys.executable, __file__, "--worker", str(path), "--seconds", str(seconds)]
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=1800).stdout
    else:
        with tempfile.TemporaryDirectory() as tmp:
            driver = Path(tmp) / "driver.pl"
            driver.write_text(
                f":- style_check(-singleton).\n:- consult('{path}').\n"
                + LOOP
                + SWI_MAIN.format(seconds=seconds)
            )
            cmd = ["swipl", "-O", str(driver)]
            out = subprocess.run(cmd, capture_output=True, text=True, timeout=1800).stdout
    found = _RESULT.search(out)
    if found is None or "failed" in out:
        raise RuntimeError(f"{engine} could not run {path.name}: {out[-300:]!r}")
    return int(found[1]), float(found[2])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--bench", type=Path, default=os.environ.get("SWI_BENCH_DIR"))
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=1.0, help="CPU [s] per run at least")
    parser.add_argument("--only", nargs="*", default=sorted(SHA256), choices=sorted(SHA256))
    parser.add_argument("--worker", type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker is not None:
        worker(args.worker, args.seconds)
        return
    subprocess.run(["sh", str(Path(__file__).with_name("setup_swipl.sh"))], check=False)
    engines = ["robocram"] + (["swipl"] if shutil.which("swipl") else [])
    best: dict[tuple[str, str], float] = {}
    print(f"load average at start: {os.getloadavg()}")
    with tempfile.TemporaryDirectory() as tmp:
        paths: dict[str, Path] = {}
        for name in args.only:
            text = program_text(name, args.bench)
            if text is None:
                print(f"{name}: not stored here; pass --bench (see the docstring)")
                continue
            paths[name] = Path(tmp) / f"{name}.pl"
            paths[name].write_text(text, encoding="utf-8")
        for _ in range(args.rounds):
            for name, path in paths.items():
                for engine in engines:
                    n, cpu = run_once(engine, path, args.seconds)
                    key = (name, engine)
                    best[key] = min(best.get(key, math.inf), cpu / n)
    print(f"load average at end:   {os.getloadavg()}")
    report(list(paths), best)


def report(names: list[str], best: dict[tuple[str, str], float]) -> None:
    """Print the table: seconds per iteration, ratios, geometric mean and worst."""
    print(f"{'program':<12}{'robocram [s]':>14}{'swipl -O [s]':>14}{'ours/SWI':>10}")
    ratios: dict[str, float] = {}
    for name in names:
        mine, ref = best[(name, "robocram")], best.get((name, "swipl"))
        if ref:
            ratios[name] = mine / ref
        ref_text = f"{ref:>14.3e}" if ref else f"{'n/a':>14}"
        ratio_text = f"{ratios[name]:>10.1f}" if name in ratios else f"{'n/a':>10}"
        print(f"{name:<12}{mine:>14.3e}{ref_text}{ratio_text}")
    if ratios:
        geo = math.exp(sum(math.log(r) for r in ratios.values()) / len(ratios))
        worst = max(ratios, key=lambda k: ratios[k])
        print(f"geomean over {len(ratios)} programs: {geo:.1f}x")
        print(f"worst: {worst} {ratios[worst]:.1f}x")


if __name__ == "__main__":
    main()

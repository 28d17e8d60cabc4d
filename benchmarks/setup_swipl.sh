#!/bin/sh
# Install SWI-Prolog (the reference system for benchmarks/logic_bench.py) when missing.
# Skips quietly when swipl is present, or when not root / apt-get is unavailable.
command -v swipl >/dev/null 2>&1 && exit 0
command -v apt-get >/dev/null 2>&1 || exit 0
[ "$(id -u)" = "0" ] || exit 0
apt-get update -qq >/dev/null 2>&1 && apt-get install -y -qq swi-prolog-nox >/dev/null 2>&1
exit 0

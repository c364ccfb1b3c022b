#!/usr/bin/env bash
# Oracle for speed work on `rapid check`: the JSON reports on the corpus and
# on generated layouts must stay byte-identical across an optimisation.
#   tests/bench/check_oracle.sh RAPID_BINARY OUTDIR [DIR...]
# writes OUTDIR/<n>.json per input; compare two OUTDIRs with `diff -r`.
set -euo pipefail
bin=$1; out=$2; shift 2
mkdir -p "$out"
i=0
for dir in "$@"; do
    "$bin" check "$dir" --format json --exit-zero >"$out/$i.json"
    i=$((i + 1))
done

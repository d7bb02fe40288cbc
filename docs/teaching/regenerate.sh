#!/usr/bin/env bash
# Regenerates docs/teaching/ (the figures and numbers of docs/teaching.md) with the built
# binary: every preset of `kinema demo`, at most 7 steps per solver plus the last, and the
# solver table. CPU only; timings (ms) change from run to run and machine to machine.
# Usage: docs/teaching/regenerate.sh [build/src/kinema]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
out=$root/docs/teaching
for preset in $("$kinema" demo list --json | python3 -c 'import json,sys; print(" ".join(p["name"] for p in json.load(sys.stdin)))'); do
  rm -rf "${out:?}/$preset"
  "$kinema" demo "$preset" --out "$out/$preset" --size 520x390 --max-steps 7
done
"$kinema" demo solver-table --out "$out/solver-table" --targets 100 > /dev/null
# Issue 23: the four integrators on the damped spring chain (no timings: the numbers are exact).
"$kinema" demo stiff-springs --out "$out/stiff-springs" --size 1500x800 > /dev/null

#!/usr/bin/env bash
# DEM throughput: debrisflow at 1 and 2 threads and LIGGGHTS 3.8 (Debian package liggghts) on
# one core, same physics (cases/bench/<case>.toml = bench/liggghts/<case>.in).
# Usage: bench/run_dem_bench.sh [build dir] [steps]   (defaults: build, 5000)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
steps="${2:-5000}"
end=$(python3 -c "print($steps * 2e-7)")
out=$(mktemp -d)
for case in box100k flume30; do
  for t in 1 2; do
    "$build/debrisflow" run "$root/cases/bench/$case.toml" --out "$out/$case-$t" --threads "$t" \
      --set time.end="$end" --quiet
    python3 -c "import json,sys; s=json.load(open('$out/$case-$t/summary.json')); \
print(f\"debrisflow $case threads=$t: {s['particle_steps_per_second']:.3g} particle-steps/s, \
{s['dem']['contacts']} contacts, {s['wall_seconds']:.1f} s\")"
  done
done
if command -v liggghts > /dev/null; then
  for case in box100k:100000 flume30:15000; do
    name=${case%%:*}
    n=${case##*:}
    (cd "$out" && sed "s/^run 5000/run $steps/" "$root/bench/liggghts/$name.in" > "$name.in" &&
       liggghts -in "$name.in" -echo none -log "lig-$name.log" | grep "Loop time" |
       awk -v s="$steps" -v n="$n" -v c="$name" \
         '{printf "liggghts %s 1 core: %.3g particle-steps/s (%s s)\n", c, n*s/$4, $4}')
  done
fi

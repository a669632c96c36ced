#!/usr/bin/env bash
# DEM throughput: debrisflow at 1 and 2 threads and LIGGGHTS 3.8 (Debian package liggghts) on
# one core, same physics (cases/bench/<case>.toml = bench/liggghts/<case>.in), run in turn
# (debrisflow 1 thread, 2 threads, LIGGGHTS) REPEATS times in one sitting; prints every run and
# the medians with the ratios. Both codes' figures are of the time loop only (debrisflow's
# summary.json particle_steps_per_second, LIGGGHTS's "Loop time").
# With a fourth argument, a baseline build dir (e.g. a build of main), its debrisflow runs too,
# in turn with the others ("base-1", "base-2"), and the medians' ratios are printed.
# Usage: bench/run_dem_bench.sh [build dir] [steps] [repeats] [baseline build dir]
#        (defaults: build, 5000, 1, none)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
steps="${2:-5000}"
repeats="${3:-1}"
baseline="${4:-}"
end=$(python3 -c "print($steps * 2e-7)")
out=$(mktemp -d)
results="$out/results.txt"
: > "$results"
have_liggghts=0
command -v liggghts > /dev/null && have_liggghts=1
for _ in $(seq "$repeats"); do
  for case in box100k:100000 flume30:15000; do
    name=${case%%:*}
    n=${case##*:}
    for t in 1 2; do
      for who in debrisflow ${baseline:+base}; do
        exe="$build/debrisflow"
        [ "$who" = base ] && exe="$baseline/debrisflow"
        "$exe" run "$root/cases/bench/$name.toml" --out "$out/$name-$t" --threads "$t" \
          --set time.end="$end" --quiet --overwrite
        python3 -c "import json; s=json.load(open('$out/$name-$t/summary.json')); \
print('$name $who-$t', s['particle_steps_per_second'], s['dem']['contacts'])" | tee -a "$results"
      done
    done
    if [ "$have_liggghts" = 1 ]; then
      (cd "$out" && sed "s/^run 5000/run $steps/" "$root/bench/liggghts/$name.in" > "$name.in" &&
         liggghts -in "$name.in" -echo none -log "lig-$name.log" | grep "Loop time" |
         awk -v s="$steps" -v n="$n" -v c="$name" '{print c, "liggghts-1", n*s/$4, "-"}') |
        tee -a "$results"
    fi
  done
done
python3 - "$results" <<'EOF'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    case, code, pss, _ = line.split()
    runs.setdefault((case, code), []).append(float(pss))
print("medians (particle-steps/s):")
for case in ("box100k", "flume30"):
    med = {code: statistics.median(v) for (c, code), v in runs.items() if c == case}
    line = f"  {case}: " + ", ".join(f"{code} {v:.3g} ({len(runs[(case, code)])} runs)"
                                     for code, v in sorted(med.items()))
    if "liggghts-1" in med:
        line += f"; per core vs LIGGGHTS {med['debrisflow-1'] / med['liggghts-1']:.2f}x"
    line += f"; 2 threads / 1 thread {med['debrisflow-2'] / med['debrisflow-1']:.2f}x"
    if "base-1" in med:
        line += (f"; against the baseline: 1 thread {med['debrisflow-1'] / med['base-1']:.3f}x,"
                 f" 2 threads {med['debrisflow-2'] / med['base-2']:.3f}x")
    print(line)
EOF

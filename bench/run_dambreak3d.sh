#!/usr/bin/env bash
# Times cases/bench/dambreak3d.toml at 1 and 2 threads (docs/performance.md).
#   bench/run_dambreak3d.sh [extra --set arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
for t in 1 2; do
    out="runs/bench/dambreak3d_t$t"
    build/debrisflow run cases/bench/dambreak3d.toml --out "$out" --overwrite --threads "$t" --quiet \
        --set output.vtk=false "$@"
    /usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timings"]
print(f"threads {s['threads']}: particles {s['particles']['total']}, steps {s['steps']}, "
      f"t = {s['simulated_time']:.3f} s, wall {s['wall_seconds']:.1f} s, "
      f"{s['particle_steps_per_second']:.3g} particle-steps/s; neighbours {t['neighbors']:.1f} s, "
      f"forces {t['forces']:.1f} s, integration {t['integration']:.1f} s, output {t['output']:.2f} s; "
      f"pair list: {s['pair_list_builds']} builds, {s['pair_list_entries']} entries")
PY
done

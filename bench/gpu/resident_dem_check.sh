#!/usr/bin/env bash
# The prepared device check of the resident DEM loop (issue #34), for a session that has a GPU:
# one call, a few minutes. Builds the CLI with the CUDA backend; runs the reduced flume, the
# type-A slit dam and box100k with --backend cuda and with --backend host_resident and compares
# their probes (tools/compare_probes.py), and grains in water (the SPH-DEM coupling); then times box100k scaled to 1 M and 6 M grains
# (200 steps each) on the device and box100k on the host's cores (default loop and resident
# loop). Prints the figures that go into docs/performance.md; writes its runs under $OUT (or
# /tmp). Written without a GPU: it has not run yet.
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${OUT:-/tmp}/resident_dem"
mkdir -p "$out"
cmake --preset cuda -DDEBRISFLOW_TESTS=OFF -DDEBRISFLOW_BENCH=OFF > "$out/configure.log"
cmake --build build-cuda --target debrisflow -j"$(nproc)" > "$out/build.log"
exe=build-cuda/debrisflow
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader || true

# figures of one run: grains, steps, wall, particle-steps/s, contacts, bytes per grain
report() {
    /usr/bin/env python3 - "$1" "$2" <<'PY'
import json, sys
s = json.load(open(sys.argv[2] + "/summary.json"))
m = s.get("dem_memory", {})
print(f"{sys.argv[1]}: {s['particles']['grains']} grains, {s['steps']} steps, "
      f"{s['wall_seconds']:.3f} s, {s['particle_steps_per_second']:.4g} particle-steps/s, "
      f"{s['dem']['contacts']} contacts, {m.get('bytes_per_grain', 0):.0f} B per grain "
      f"({m.get('backend', 'host')})")
PY
}

common=(--overwrite --quiet --set output.vtk=false)
# The device fuses multiply-adds, so the runs agree to round-off, not bitwise; granular
# collisions amplify it, so the runs are short.
for run in flume/flume30_reduced.toml:0.02: papers/slit_dam_dem/typeA.toml:0.03:dem.settle=false \
    bench/box100k.toml:2e-5:; do
    IFS=: read -r file end set <<<"$run"
    name=$(basename "$file" .toml)
    extra=()
    [ -n "$set" ] && extra=(--set "$set")
    for b in host_resident cuda; do
        "$exe" run "cases/$file" --out "$out/${name}_$b" --backend $b --set time.end="$end" \
            "${extra[@]}" "${common[@]}"
    done
    report "cuda, $name" "$out/${name}_cuda"
    python3 tools/compare_probes.py "$out/${name}_host_resident" "$out/${name}_cuda" \
        --tolerance 1e-6 || echo "DIFFERENCE: $name on the device differs beyond 1e-6"
done

# Grains in water, both phases and their drag coupling on the device
# (coupling/resident_sph_dem.hpp): the benchmark tank at dp = 20 mm with 800 grains packed above
# its floor (the case of ResidentBackend.GrainsInWater), the final grains compared; then the
# whole tank (64,000 fluid particles, 5,000 grains) timed on the device and on the host.
tank=cases/bench/sph_dem_tank.toml
small=(--set dp=0.02 --set grains.0.count=800 --set time.end=0.05
    --set 'grains.0.region={shape="box", min=[0.1,0.1,0.0], max=[0.16,0.16,0.03]}')
for b in host_resident cuda; do
    "$exe" run $tank --out "$out/tank_small_$b" --backend $b "${small[@]}" "${common[@]}"
done
python3 - "$out/tank_small_host_resident" "$out/tank_small_cuda" <<'PY' || echo "DIFFERENCE: tank"
import csv, sys
rows = [list(csv.reader(open(d + "/grains_final.csv")))[1:] for d in sys.argv[1:]]
worst = max(abs(float(a[k]) - float(b[k])) for a, b in zip(*rows) for k in range(3))
print(f"tank, 800 grains in water: largest position difference {worst:.3e} m (cuda vs host_resident)")
sys.exit(0 if worst < 1e-6 else 1)
PY
for b in cuda host; do
    "$exe" run $tank --out "$out/tank_$b" --backend $b "${common[@]}"
    report "$b, sph_dem_tank (64,000 particles, 5,000 grains), 0.01 s" "$out/tank_$b"
done

# Throughput: box100k's lattice of 10 mm spheres scaled (grains = 100 x 100 x 100, 200 x 200 x
# 150), 200 steps of 2e-7 s.
box=cases/bench/box100k.toml
for size in 0.5:0.4 1:1 2:1.5; do
    IFS=: read -r w h <<<"$size"
    read -r dw dh th <<<"$(python3 -c "print($w + 0.01, $h + 0.11, $h + 0.1)")"
    scale=(--set "domain.max=[$dw, $dw, $dh]" --set "grains.0.region.max=[$w, $w, $h]"
        --set "wall.0.max=[$w, $w, $th]" --set time.end=4e-5)
    "$exe" check $box "${scale[@]}" | grep -E "^dem:"
    "$exe" run $box --out "$out/cuda_$w" --backend cuda "${scale[@]}" "${common[@]}"
    report "cuda, box ${w} m, 200 steps" "$out/cuda_$w"
done
"$exe" run $box --out "$out/host_resident" --backend host_resident --set time.end=4e-5 "${common[@]}"
report "host_resident, $(nproc) threads, box100k, 200 steps" "$out/host_resident"
"$exe" run $box --out "$out/host" --set time.end=4e-5 "${common[@]}"
report "host, $(nproc) threads, box100k, 200 steps" "$out/host"

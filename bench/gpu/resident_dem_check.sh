#!/usr/bin/env bash
# The prepared device check of the resident DEM loop (issue #34), for a session that has a GPU:
# one call, a few minutes. Builds the CLI with the CUDA backend; runs the reduced flume, the
# type-A slit dam and box100k with --backend cuda and with --backend host_resident and compares
# their probes (tools/compare_probes.py); then times box100k scaled to 1 M and 6 M grains
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

#!/usr/bin/env bash
# The prepared device check of the resident SPH loop (issue #33), for a session that has a GPU:
# one call, a few minutes. Builds the CLI with the CUDA backend, runs the 3D dam break to 0.05 s
# with --backend cuda and with --backend host_resident and compares their probes
# (tools/compare_probes.py), the same for a gate with an inlet and an outlet, the floating box
# and water against an elastic wall, then times the device at 0.18, 0.79 and 2.2 M particles (200
# steps each) and the host's resident loop at 0.18 M on every core. Prints the figures that go
# into docs/performance.md ("The resident loop on a GPU"); writes its runs under $OUT (or /tmp).
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${OUT:-/tmp}/resident"
mkdir -p "$out"
cmake --preset cuda -DDEBRISFLOW_TESTS=OFF -DDEBRISFLOW_BENCH=OFF > "$out/configure.log"
cmake --build build-cuda --target debrisflow -j"$(nproc)" > "$out/build.log"
exe=build-cuda/debrisflow
case=cases/bench/dambreak3d.toml
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader || true

# figures of one run: particles, steps, wall, particle-steps/s, bytes per particle
report() {
    /usr/bin/env python3 - "$1" "$2" <<'PY'
import json, sys
s = json.load(open(sys.argv[2] + "/summary.json"))
m = s.get("sph_memory", {})
print(f"{sys.argv[1]}: {s['particles']['total']} particles, {s['steps']} steps, "
      f"{s['wall_seconds']:.3f} s, {s['particle_steps_per_second']:.4g} particle-steps/s, "
      f"{m.get('bytes_per_particle', 0):.1f} B per particle ({m.get('backend')})")
PY
}

common=(--overwrite --quiet --set output.vtk=false)
"$exe" run "$case" --out "$out/host" --backend host_resident --set time.end=0.05 "${common[@]}"
"$exe" run "$case" --out "$out/cuda" --backend cuda --set time.end=0.05 "${common[@]}"
report "host_resident, 0.05 s" "$out/host"
report "cuda, 0.05 s" "$out/cuda"
# The device fuses multiply-adds, so the runs agree to round-off, not bitwise.
python3 tools/compare_probes.py "$out/host" "$out/cuda" --tolerance 1e-6 \
    || echo "DIFFERENCE: the device's probes differ from the host's beyond 1e-6"

# Inlet, outlet and gate; a floating body (loads reduced per body on the device); an elastic
# wall (SPH-FEM: the carried particles moved from the nodes, their loads compacted there).
for extra in validation/gate_inlet_outlet2d.toml:0.3 rigid/floating_box2d.toml:0.2 \
    fem/water_on_elastic_wall2d.toml:0.1; do
    name=$(basename "${extra%%:*}" .toml)
    for b in host_resident cuda; do
        "$exe" run "cases/${extra%%:*}" --out "$out/${name}_$b" --backend $b \
            --set time.end="${extra##*:}" "${common[@]}"
    done
    report "cuda, $name" "$out/${name}_cuda"
    python3 tools/compare_probes.py "$out/${name}_host_resident" "$out/${name}_cuda" \
        --tolerance 1e-6 || echo "DIFFERENCE: $name on the device differs beyond 1e-6"
done
for dp in 0.0085 0.005 0.0035; do
    dt=$("$exe" check "$case" --set dp=$dp | sed -n 's/^time step: \([0-9.e+-]*\) s.*/\1/p')
    end=$(python3 -c "print(200 * $dt)")
    "$exe" run "$case" --out "$out/cuda_$dp" --backend cuda --set dp=$dp --set time.end=$end \
        "${common[@]}"
    report "cuda, dp = $dp m, 200 steps" "$out/cuda_$dp"
    if [ "$dp" = 0.0085 ]; then
        "$exe" run "$case" --out "$out/host_$dp" --backend host_resident --set dp=$dp \
            --set time.end=$end "${common[@]}"
        report "host_resident, $(nproc) threads, dp = $dp m, 200 steps" "$out/host_$dp"
        "$exe" run "$case" --out "$out/list_$dp" --set dp=$dp --set time.end=$end "${common[@]}"
        report "host (list), $(nproc) threads, dp = $dp m, 200 steps" "$out/list_$dp"
    fi
done

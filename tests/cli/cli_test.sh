#!/usr/bin/env bash
# Command-line contract: output layout, exit codes 2 (bad input), 3 (unstable run, output
# kept) and 130 (stopped by a signal, output kept), error messages naming file:line:column and key.
set -u
exe="$1"; src="$2"; out="$3"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
demo="$src/cases/dambreak2d.toml"

"$exe" run "$demo" --out "$out/run" --set time.end=0.01 --set output.vtk_every=0.005 --quiet \
    || fail "short run failed"
for f in case.toml log.txt summary.json vtk/particles.pvd vtk/particles_00000.vtu probes/sensor1.csv; do
    [ -s "$out/run/$f" ] || fail "missing $f"
done
head -1 "$out/run/probes/sensor1.csv" | grep -q '^time \[s\],p \[Pa\]$' || fail "probe header"
for key in particles steps simulated_time wall_seconds particle_steps_per_second threads probes; do
    grep -q "\"$key\"" "$out/run/summary.json" || fail "summary lacks $key"
done
grep -q 'time.end|end = 0.01' "$out/run/case.toml" || grep -q 'end = 0.01' "$out/run/case.toml" \
    || fail "resolved case lacks the override"

"$exe" check "$demo" --set sph.viscosty=1 > "$out/bad.txt" 2>&1; rc=$?
[ $rc -eq 2 ] || fail "unknown key: exit $rc, expected 2"
grep -q "unknown key 'sph.viscosty'" "$out/bad.txt" || fail "unknown key message: $(cat "$out/bad.txt")"

printf 'dp = 0.01\n[time]\nend = "soon"\n' > "$out/badtype.toml"
"$exe" check "$out/badtype.toml" > "$out/badtype.txt" 2>&1; rc=$?
[ $rc -eq 2 ] || fail "wrong type: exit $rc"
grep -q "badtype.toml:3:7: key 'time.end': expected a number" "$out/badtype.txt" \
    || fail "wrong type message: $(cat "$out/badtype.txt")"

"$exe" check "$out/missing.toml" > /dev/null 2>&1; rc=$?
[ $rc -eq 2 ] || fail "missing file: exit $rc"

# summary.json is valid JSON.
/usr/bin/python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$out/run/summary.json" \
    || fail "summary.json is not valid JSON"

# An output folder that holds a run's results is refused (exit 2) and left as it was; with
# --overwrite its old frames and probes are removed, so no stale frame stays beside the new
# series.
"$exe" run "$demo" --out "$out/run" --set time.end=0.005 --quiet > "$out/reuse.txt" 2>&1; rc=$?
[ $rc -eq 2 ] || fail "reused output folder: exit $rc, expected 2"
grep -q "holds the results of an earlier run" "$out/reuse.txt" || fail "reuse message: $(cat "$out/reuse.txt")"
[ -s "$out/run/vtk/particles_00002.vtu" ] || fail "the refused run touched the old results"
"$exe" run "$demo" --out "$out/run" --set time.end=0.002 --quiet --overwrite || fail "--overwrite run"
[ ! -e "$out/run/vtk/particles_00002.vtu" ] || fail "--overwrite left a stale frame"
[ "$(grep -c '<DataSet' "$out/run/vtk/particles.pvd")" -eq "$(ls "$out/run/vtk/"*.vtu | wc -l)" ] \
    || fail "the .pvd series and the frames on disk disagree"

# Fluid thrown upwards out of the domain: the run must stop (exit 3) with a message saying
# where, keeping summary.json.
"$exe" run "$demo" --out "$out/unstable" --set fluid.0.velocity=[0,5] --set time.end=0.5 \
    --set domain.exit=stop --quiet \
    > "$out/unstable.txt" 2>&1; rc=$?
[ $rc -eq 3 ] || fail "unstable run: exit $rc, expected 3"
grep -q "left the domain" "$out/unstable.txt" || fail "instability message: $(cat "$out/unstable.txt")"
grep -q '"status": "unstable"' "$out/unstable/summary.json" || fail "unstable summary"
/usr/bin/python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$out/unstable/summary.json" \
    || fail "the unstable run's summary.json is not valid JSON"
[ -s "$out/unstable/vtk/particles.pvd" ] || fail "unstable run lost its output"

# A sound speed that the column at rest accepts (c0 = 3 sqrt(g H) = 5.1 m/s compresses its
# bottom by 9 %, under the 10 % that `check` refuses) but that the dam break's impact outruns:
# the surge hits the far wall at about 2.6 m/s, Mach 0.5, and squeezes the fluid beyond 30 % of
# rho0. The run stops (exit 3) saying so, on the host and on the resident backend's path,
# instead of finishing with water at twice its density. (Fluid thrown at 20 m/s, faster than
# c0, is refused before the run: cli_bad_input.fluid_faster_than_c0.)
for backend in host host_resident; do
    "$exe" run "$demo" --out "$out/squeezed_$backend" --set sph.c0_coefficient=3 \
        --set time.end=0.5 --backend "$backend" --quiet > "$out/squeezed.txt" 2>&1; rc=$?
    [ $rc -eq 3 ] || fail "squeezed fluid ($backend): exit $rc, expected 3"
    grep -q "fluid compressed beyond the weakly-compressible range .*rho/rho0 = 1.3" \
        "$out/squeezed.txt" || fail "squeezed fluid message ($backend): $(cat "$out/squeezed.txt")"
done
# The same with the default domain.exit = "remove": the fluid that leaves is removed and counted
# by face (all of it through the top, z+), with a warning once over 1 % of the fluid's mass.
{ cat "$demo"; printf '\n[[probe]]\nname = "lost"\ntype = "domain_exit"\nevery = 0.01\n'; } \
    > "$out/leaving.toml"
"$exe" run "$out/leaving.toml" --out "$out/leaving" --set fluid.0.velocity=[0,5] \
    --set time.end=0.12 --quiet > "$out/leaving.txt" 2>&1 \
    || fail "run with fluid leaving the domain: $(tail -3 "$out/leaving.txt")"
grep -q "WARNING: .*fluid particles that left the domain" "$out/leaving/log.txt" \
    || fail "no lost-mass warning: $(cat "$out/leaving/log.txt")"
/usr/bin/python3 - "$out/leaving" <<'PY' || fail "left_domain tally"
import csv, json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
lost = s["left_domain"]["fluid"]
assert s["left_domain"]["policy"] == "remove", s["left_domain"]
assert lost["count"] > 0 and lost["faces"]["zmax"]["count"] == lost["count"], lost
assert s["particles_end"]["fluid"] == s["particles"]["fluid"] - lost["count"], s
rows = list(csv.reader(open(sys.argv[1] + "/probes/lost.csv")))
assert rows[0][1] == "fluid_count [-]" and int(float(rows[-1][1])) == lost["count"], rows[-1]
PY
# SIGTERM (or Ctrl-C) during a run: it stops after the current step (exit 130), keeping the
# probes, frames and a summary that says so.
"$exe" run "$demo" --out "$out/stopped" --set time.end=60 --threads 1 --quiet \
    > "$out/stopped.txt" 2>&1 &
pid=$!
for _ in $(seq 600); do
    [ -s "$out/stopped/vtk/particles_00000.vtu" ] && break
    sleep 0.1
done
sleep 1
kill -TERM $pid
wait $pid; rc=$?
[ $rc -eq 130 ] || fail "stopped run: exit $rc, expected 130: $(cat "$out/stopped.txt")"
grep -q "stopped on request (signal 15)" "$out/stopped.txt" || fail "stop message: $(cat "$out/stopped.txt")"
grep -q '"status": "interrupted"' "$out/stopped/summary.json" || fail "interrupted summary"
[ "$(wc -l < "$out/stopped/probes/sensor1.csv")" -ge 3 ] || fail "stopped run lost its probe rows"
# The same while grains settle before the run (dem.settle, here set never to reach its ratio):
# the stop comes at the end of the settling step, not at the end of dem.settle_max_time.
"$exe" run "$src/cases/deposits/column_collapse2d.toml" --out "$out/settling" --threads 1 \
    --quiet --set dem.settle=true --set dem.settle_ratio=1e-12 --set dem.settle_max_time=1000 \
    > "$out/settling.txt" 2>&1 &
pid=$!
for _ in $(seq 600); do
    grep -q "^dem:" "$out/settling/log.txt" 2> /dev/null && break
    sleep 0.1
done
sleep 1
kill -TERM $pid
for _ in $(seq 300); do
    kill -0 $pid 2> /dev/null || break
    sleep 0.1
done
if kill -0 $pid 2> /dev/null; then
    kill -KILL $pid
    fail "SIGTERM while settling: still running 30 s later"
fi
wait $pid; rc=$?
[ $rc -eq 130 ] || fail "stopped settling: exit $rc, expected 130: $(cat "$out/settling.txt")"
grep -q "while settling the grains" "$out/settling.txt" || fail "settling stop message: $(cat "$out/settling.txt")"
echo "cli contract OK"

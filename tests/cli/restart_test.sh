#!/usr/bin/env bash
# Checkpoint and restart (issue #31). For fluid cases (a gate, Laminar+SPS, Herschel-Bulkley,
# an inlet and an outlet), grain cases (a settled column behind a gate; a hopper feed with its
# random sizes; clumps; clumps with a feed; the granular flume; the column, the clumps, the
# clumps with a feed and the flume on the resident DEM loop; discs pushed across the planes of
# a mass flux, a discharge and a trapping probe on both loops), rigid-body cases (a block sliding in water; the
# reduced container case; a hinged disc and a box on a spring falling into grains, on the host's
# DEM loop and on the resident one; mesh rocks
# from a feed) and coupled cases (FEM alone; SPH-FEM, an eroding SPH-FEM wall, grains on a FEM
# plate and SPH-DEM drag on the host's loops and on the resident ones; the SPH-DEM-FEM retaining
# dam), a run to T and the same run restarted from its checkpoint near
# T/2 write byte-identical probe files, VTK frames and final state (the final checkpoint holds
# every array), at the same thread count. Also: a stop by SIGTERM writes a checkpoint to
# continue from; a kill while a checkpoint is written leaves the previous one usable; damaged,
# truncated and mismatched checkpoints are refused with exit 2.
set -u
exe="$1"; src="$2"; out="$3"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
newest() { ls "$1"/checkpoint/step_*.dfc | sort | tail -1; }

# same_files A B what: every probe file and frame of A is in B, byte for byte.
same_files() {
    for f in $(cd "$1" && ls probes/* vtk/*); do
        cmp -s "$1/$f" "$2/$f" || fail "$3: $f differs from the uninterrupted run"
    done
}

# same_output A B what: as same_files, no other files, and the same final checkpoint.
same_output() {
    [ "$(cd "$1" && ls probes vtk)" = "$(cd "$2" && ls probes vtk)" ] \
        || fail "$3: the restarted run wrote other files: $(cd "$2" && ls probes vtk)"
    same_files "$1" "$2" "$3"
    cmp -s "$(newest "$1")" "$(newest "$2")" || fail "$3: the final state differs"
    [ "$(basename "$(newest "$1")")" = "$(basename "$(newest "$2")")" ] \
        || fail "$3: the final step count differs"
}

inputs="$src/tests/cli/inputs"
while read -r name file end extra; do
    half=$(/usr/bin/python3 -c "print($end / 2)")
    a="$out/$name.full"; b="$out/$name.restarted"
    # shellcheck disable=SC2086 # $extra: further options, split into words
    "$exe" run "$file" --out "$a" --threads 2 --quiet --set time.end=$end \
        --set output.checkpoint_every=$half $extra || fail "$name: the full run failed"
    [ "$(ls "$a"/checkpoint/*.dfc | wc -l)" -eq 2 ] || fail "$name: expected 2 checkpoints"
    cp -r "$a" "$b"
    rm "$(newest "$b")" # keep the one near T/2
    # shellcheck disable=SC2086
    "$exe" run "$file" --restart "$b" --threads 2 --quiet --set time.end=$end \
        --set output.checkpoint_every=$half $extra || fail "$name: the restart failed"
    grep -q "restarted from $b/checkpoint/step_" "$b/log.txt" || fail "$name: log lacks the restart"
    same_output "$a" "$b" "$name"
done <<CASES
dambreak $src/cases/dambreak2d.toml 0.1
gate_sps $inputs/restart_gate_sps2d.toml 0.3
gate_sps_resident $inputs/restart_gate_sps_resident2d.toml 0.3
hb_inlet_outlet $inputs/restart_hb_inlet2d.toml 1.2
gate_inlet_outlet_cells $inputs/restart_gate_inlet_outlet_cells2d.toml 0.4
dem_column_settled_gate $src/cases/deposits/column_collapse2d.toml 0.2
dem_column_resident $src/cases/deposits/column_collapse2d.toml 0.2 --backend host_resident
dem_flume_resident $src/cases/flume/flume30_reduced.toml 0.01 --backend host_resident
dem_hopper_feed_baffles $src/cases/debris/baffles_hopper_dem.toml 0.06
dem_clumps $src/cases/deposits/column_collapse2d_clumps.toml 0.1
dem_clumps_resident $src/cases/deposits/column_collapse2d_clumps.toml 0.1 --backend host_resident
clumps_feed $inputs/clumps_feed2d.toml 0.2
clumps_feed_resident $inputs/clumps_feed2d.toml 0.2 --backend host_resident
pushed_across $inputs/pushed_across2d.toml 0.25
pushed_across_resident $inputs/pushed_across2d.toml 0.25 --backend host_resident
grains_on_plate $inputs/restart_grains_on_plate3d.toml 0.02
grains_on_plate_resident $inputs/restart_grains_on_plate3d.toml 0.02 --backend host_resident
dem_flume $src/cases/flume/flume30_reduced.toml 0.01
body_in_fluid $src/cases/rigid/sliding_block2d.toml 0.3
container_reduced $src/cases/papers/container_dambreak2d_reduced.toml 0.02
bodies_grains_joints $inputs/restart_bodies_grains2d.toml 0.2
bodies_grains_joints_resident $inputs/restart_bodies_grains2d.toml 0.2 --backend host_resident
rock_feed $inputs/restart_rock_feed3d.toml 0.6
fem_cantilever $src/cases/fem/cantilever_steel.toml 0.02
sph_fem_elastic_gate $src/cases/fem/elastic_gate2d.toml 0.06
sph_fem_elastic_gate_resident $src/cases/fem/elastic_gate2d.toml 0.06 --backend host_resident
sph_fem_eroding_wall $src/cases/fem/water_on_elastic_wall2d.toml 0.1 --set dp=0.01 --set fem_material.0.youngs_modulus=2e6 --set fem_material.0.erosion_strain=0.005 --set solid.0.max=[0.38,0.4] --set solid.0.divisions=[8,40] --set wall.0.max=[0.6,0.45] --set domain.max=[0.7,0.6]
sph_fem_eroding_wall_resident $src/cases/fem/water_on_elastic_wall2d.toml 0.1 --backend host_resident --set dp=0.01 --set fem_material.0.youngs_modulus=2e6 --set fem_material.0.erosion_strain=0.005 --set solid.0.max=[0.38,0.4] --set solid.0.divisions=[8,40] --set wall.0.max=[0.6,0.45] --set domain.max=[0.7,0.6]
sph_dem_drag_settling $src/cases/coupling/settling_grain.toml 0.1
sph_dem_drag_settling_resident $src/cases/coupling/settling_grain.toml 0.1 --backend host_resident
sph_dem_fem_retaining_dam $src/cases/papers/retaining_dam.toml 0.1
CASES
gate="$inputs/restart_gate_sps2d.toml"
full="$out/gate_sps.full"

# SIGTERM mid-run: exit 130, a checkpoint at the stop, and the restart continues as if never
# stopped (the run without checkpoints is the same run: writing one changes nothing).
s="$out/sigterm"
"$exe" run "$gate" --out "$s" --threads 2 --quiet --set output.progress_seconds=0.05 &
pid=$!
for _ in $(seq 1 600); do
    grep -q "step [1-9]" "$s/log.txt" 2>/dev/null && break
    sleep 0.01
done
kill -TERM $pid; wait $pid; rc=$?
[ $rc -eq 130 ] || fail "SIGTERM: exit $rc, expected 130"
ls "$s"/checkpoint/step_*.dfc > /dev/null 2>&1 || fail "SIGTERM wrote no checkpoint"
"$exe" run "$gate" --restart "$s" --threads 2 --quiet --set output.checkpoint_every=0.15 \
    || fail "restart after SIGTERM failed"
same_files "$full" "$s" "after SIGTERM"

# output.checkpoint_wall: checkpoints by wall-clock time (here every 0.06 s of a ~1 s run).
w="$out/wall"
"$exe" run "$gate" --out "$w" --threads 2 --quiet --set output.checkpoint_wall=0.001 \
    || fail "run with checkpoint_wall failed"
[ "$(grep -c ': checkpoint ' "$w/log.txt")" -ge 3 ] \
    || fail "checkpoint_wall: $(grep -c ': checkpoint ' "$w/log.txt") checkpoints written"

# SIGKILL while the second checkpoint is being written: the first stays usable.
k="$out/killed"
DEBRISFLOW_CHECKPOINT_KILL_AFTER_BYTES=4000 "$exe" run "$gate" --out "$k" --threads 2 --quiet \
    --set output.checkpoint_every=0.1 > /dev/null 2>&1; rc=$?
[ $rc -eq 137 ] || fail "fault injection: exit $rc, expected 137 (SIGKILL)"
[ "$(ls "$k"/checkpoint/*.dfc | wc -l)" -eq 1 ] || fail "killed run: expected 1 complete checkpoint"
ls "$k"/checkpoint/*.tmp > /dev/null 2>&1 || fail "killed run: no partial temporary file"
"$exe" run "$gate" --restart "$k" --threads 2 --quiet --set output.checkpoint_every=0.15 \
    || fail "restart after SIGKILL failed"
same_files "$full" "$k" "after SIGKILL"
ls "$k"/checkpoint/*.tmp > /dev/null 2>&1 && fail "the partial temporary file was left behind"

# A restart of a restart: the restarted run checkpoints at its first step (before a probe is
# due) and is killed at its second checkpoint; continuing from that first checkpoint still
# gives the uninterrupted run's files (the probe files' lengths are right before any new row).
r="$out/twice"; cp -r "$full" "$r"
rm "$(newest "$r")"
DEBRISFLOW_CHECKPOINT_KILL_AFTER_BYTES=100 "$exe" run "$gate" --restart "$r" --threads 2 \
    --quiet --set output.checkpoint_every=1e-5 > /dev/null 2>&1; rc=$?
[ $rc -eq 137 ] || fail "restart of a restart: exit $rc, expected 137 (SIGKILL)"
"$exe" run "$gate" --restart "$r" --threads 2 --quiet --set output.checkpoint_every=0.15 \
    || fail "restart of a restart failed"
same_files "$full" "$r" "restart of a restart"

# Refusals: exit 2 and a message naming the file and the problem.
refused() { # what expected-message command...
    local what="$1" msg="$2"; shift 2
    "$@" > "$out/refused.txt" 2>&1; local rc=$?
    [ $rc -eq 2 ] || fail "$what: exit $rc, expected 2: $(cat "$out/refused.txt")"
    grep -q -- "$msg" "$out/refused.txt" || fail "$what: message: $(cat "$out/refused.txt")"
}
c="$out/corrupt"; cp -r "$full" "$c"
f=$(newest "$c")
printf '\x55' | dd of="$f" bs=1 seek=5000 conv=notrunc status=none
refused corrupted "checkpoint $f: corrupted" "$exe" run "$gate" --restart "$c" --quiet
t="$out/truncated"; cp -r "$full" "$t"
f=$(newest "$t"); truncate -s -100 "$f"
refused truncated "checkpoint $f: truncated" "$exe" run "$gate" --restart "$t" --quiet
m="$out/mismatch"; cp -r "$full" "$m"
refused "another case" "was written for another case" \
    "$exe" run "$gate" --restart "$m" --quiet --set sph.c0=25
refused "no checkpoint" "no checkpoint" "$exe" run "$gate" --restart "$out" --quiet

# A finished run is extended by a larger time.end (output keys and time.end may change).
e="$out/extended"; cp -r "$full" "$e"
"$exe" run "$gate" --restart "$e" --quiet --set time.end=0.35 --set output.vtk_every=0.1 \
    || fail "extending a finished run failed"
tail -1 "$e/probes/p1.csv" | grep -q '^0.35,' || fail "extended run: p1 ends at $(tail -1 "$e/probes/p1.csv")"
echo "restart: all checks passed"

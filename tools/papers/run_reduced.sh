#!/bin/bash
# Runs the reduced variants of the paper cases (cases/papers/, docs/validation.md "Paper
# reproductions") into runs/papers/<run>, JOBS runs at a time (default 2) with THREADS threads
# each (default 1), skipping runs whose summary.json says they completed. Then regenerate the
# report with
#   /usr/bin/python3 tools/papers/report.py runs/papers --figures docs/img
# Exits non-zero when a run fails (its output so far is kept). Also `ctest -L paper`.
# Usage: tools/papers/run_reduced.sh [flume|flume_rr|slit|slit10|baffles|check|check15|container|dam ...]
# (default: all but flume_rr, slit10 and check15; the slit check dam of section A takes 13-20 min per 6 s run
# on one thread)
set -u
cd "$(dirname "$0")/../.."
OUT=${OUT:-runs/papers}
JOBS=${JOBS:-2}
BIN=${BIN:-build/debrisflow}
THREADS=${THREADS:-1}
mkdir -p "$OUT"
SOFT="--set material.0.kn=1e6 --set material.0.kt=1e6 --set material.1.kn=1e6 --set material.1.kt=1e6"
P=cases/papers

list() {
  case "$1" in
  flume) # section E: 2D discs, all sizes (3 mm with contacts softened to 1e6 N/m: cost); 3D 38 mm,
    # and 23 mm at 30 degrees
    for s in 10 30; do
      for k in free barrier; do
        echo "E_${k}${s}_2d_d3 $P/granular_flume/${k}${s}_2d.toml --set grains.0.diameter=0.003 $SOFT"
        for d in 10 23 38; do
          echo "E_${k}${s}_2d_d$d $P/granular_flume/${k}${s}_2d.toml --set grains.0.diameter=0.0$d"
        done
        echo "E_${k}${s}_3d_d38 $P/granular_flume/${k}${s}_3d.toml --set grains.0.diameter=0.038"
      done
    done
    echo "E_free30_3d_d23 $P/granular_flume/free30_3d.toml --set grains.0.diameter=0.023"
    echo "E_barrier30_3d_d23 $P/granular_flume/barrier30_3d.toml --set grains.0.diameter=0.023"
    ;;
  flume_rr) # section E, 2D discs with rolling resistance: EPSD mu_r = 0.2 on grains and flume,
    # calibrated on glass-bead column collapses (docs/validation.md "Deposit shape"), 10-38 mm
    local rr="--set 'dem.rolling=\"epsd\"' --set material.0.rolling_friction=0.2"
    rr="$rr --set material.1.rolling_friction=0.2"
    for s in 10 30; do
      for k in free barrier; do
        for d in 10 23 38; do
          echo "E_${k}${s}_2d_d${d}_rr $P/granular_flume/${k}${s}_2d.toml --set grains.0.diameter=0.0$d $rr"
        done
      done
    done
    ;;
  slit) # section B, two-level DEM: Type A SD5 (the paper's 12,393 grains), Type B with SD5 fines
    echo "B_slitA_sd5 $P/slit_dam_dem/typeA.toml"
    # two more packings of the same grains (the spread of the peak), and A-SD5(2): 10,697 grains
    for k in 2 3; do echo "B_slitA_sd5_seed$k $P/slit_dam_dem/typeA.toml --set grains.0.seed=$k"; done
    echo "B_slitA_sd5_n10697 $P/slit_dam_dem/typeA.toml --set grains.0.count=10697"
    for n in 4 16 32; do
      echo "B_slitB_sd5_${n}b $P/slit_dam_dem/typeB.toml --set grains.0.diameter=0.01 --set grains.0.count=12393 --set grains.1.count=$n"
    done
    ;;
  slit10) # section B, Type A SD10 (the paper's 93,747 grains of 5 mm) to 1.5 s, past the peak:
    # not in the default list (2.2 h on 2 threads with the settling: THREADS=2 JOBS=1)
    echo "B_slitA_sd10 $P/slit_dam_dem/typeA.toml --set grains.0.diameter=0.005 --set grains.0.count=93747 --set time.end=1.5 --set probe.2.window=[0.0,1.5]"
    ;;
  baffles) # section B, SPH-DEM: slurry viscosity 0.1, 1, 5 m2/s; boulders on the slurry's
    # surface (the case), and on the bed in its front part, behind it and ahead of it
    local -A at=([bed]="7.8 6.6 0.5" [up]="1.8 0.6 0.5" [ahead]="11.0 9.8 0.5")
    for nu in 0.1 1 5; do
      echo "B_baffles_nu$nu $P/baffles_boulders.toml --set sph.nu=$nu"
      for v in bed up ahead; do
        read -r x1 x2 z <<<"${at[$v]}"
        local b="--set body.0.center=[$x1,1.0,$z] --set body.1.center=[$x1,3.0,$z]"
        b="$b --set body.2.center=[$x1,5.0,$z] --set body.3.center=[$x2,2.0,$z]"
        b="$b --set body.4.center=[$x2,4.0,$z]"
        echo "B_baffles_${v}_nu$nu $P/baffles_boulders.toml --set sph.nu=$nu $b"
      done
    done
    ;;
  check) # section A: trapping efficiency for s/d95 = 1.18, 1.36, 1.49 (reduced slice)
    for s in 0.093:1.18 0.107:1.36 0.118:1.49; do
      echo "A_check_s${s#*:} $P/slit_check_dam_reduced.toml --set structure.1.slit_width=${s%:*}"
      for k in 2 3 4 5 6 7; do # further hopper seeds
        echo "A_check_s${s#*:}_seed$k $P/slit_check_dam_reduced.toml --set structure.1.slit_width=${s%:*} --set feed.0.seed=$k"
      done
    done
    ;;
  check15) # section A over the paper's 15 s counting window (3-18 s): ~1.3 h of one core per run;
    # not in the default list
    for s in 0.093:1.18 0.107:1.36 0.118:1.49; do
      echo "A_check_s${s#*:}_w15 $P/slit_check_dam_reduced.toml --set structure.1.slit_width=${s%:*} --set time.end=18 --set probe.1.window=[3.0,18.0]"
    done
    ;;
  container) # section C: 2D slice at the paper's dp
    echo "C_container2d $P/container_dambreak2d_reduced.toml"
    ;;
  dam) # section D: the four dam-groove slopes
    for b in 20 30 40 50; do
      echo "D_dam$b $P/retaining_dam.toml --set structure.0.slope_deg=$b"
    done
    ;;
  esac
}

one() { # NAME CASE ARGS...
  local name=$1 case=$2
  shift 2
  if grep -q '"status": "completed"' "$OUT/$name/summary.json" 2>/dev/null; then
    echo "skip $name (done)"
    return
  fi
  if ! mkdir "$OUT/$name.lock" 2>/dev/null; then
    echo "skip $name (another invocation runs it; remove $OUT/$name.lock if none does)"
    return
  fi
  local t0=$SECONDS
  "$BIN" run "$case" --out "$OUT/$name" --overwrite --threads "$THREADS" "$@" >"$OUT/$name.log" 2>&1
  local rc=$?
  rmdir "$OUT/$name.lock"
  echo "$name: exit $rc after $((SECONDS - t0)) s"
  return $rc
}
export -f one
export OUT BIN THREADS

sections=${*:-flume slit baffles check container dam}
for s in $sections; do list "$s"; done | xargs -P "$JOBS" -L 1 bash -c 'one "$@"' _

#!/usr/bin/env bash
# The whole prepared device check for a session that has a GPU, as one call of under ten
# minutes (a session has about fifteen minutes of device time in all): the resident SPH loop
# (resident_check.sh, issue #33) and then the resident DEM loop with grains in water
# (resident_dem_check.sh, issue #34), each bounded so that the first cannot starve the second;
# the CLI is built once (the second build finds it up to date). Runs go under $OUT (or /tmp);
# the printed figures go into docs/performance.md. Written without a GPU: it has not run yet.
set -u
cd "$(dirname "$0")/../.."
export OUT="${OUT:-/tmp}"
echo "== resident SPH loop (issue #33)"
timeout 300 bash bench/gpu/resident_check.sh || echo "resident_check.sh stopped: exit $?"
echo "== resident DEM loop and grains in water (issue #34)"
timeout 240 bash bench/gpu/resident_dem_check.sh || echo "resident_dem_check.sh stopped: exit $?"

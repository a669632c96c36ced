#!/usr/bin/env python3
"""Compare a body track (or any probe CSV) with a reference series, as in the container
paper (section C of seed_experiments.md):

  nRMSE = RMSE / L         for positions/lengths (L: a length, e.g. the reservoir depth h0)
  nRMSE = RMSE / sqrt(g h0) for velocities
  |ME|  = |mean(sim - ref)|
  MDE   = mean 2D distance between simulated and reference points (two columns)

The simulation is interpolated linearly onto the reference times that it covers.

Usage:
  tools/compare_track.py RUN.csv REF.csv --columns "x [m]" "y [m]" --length 0.4
  tools/compare_track.py RUN.csv REF.csv --columns "vx [m/s]" "vy [m/s]" --velocity --h0 0.4
REF.csv: a header line; first column time [s], then one column per compared quantity in the
order of --columns (names may differ). Writes a table, and JSON with --json.
"""
import argparse
import json
import math
import sys

import numpy as np


def read_csv(path):
    with open(path) as f:
        header = [h.strip() for h in f.readline().split(",")]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return header, data


def compare(t_sim, sim_cols, t_ref, ref_cols):
    """Metrics of each column and the mean distance of the first two."""
    lo, hi = t_sim[0], t_sim[-1]
    keep = (t_ref >= lo) & (t_ref <= hi)
    if keep.sum() < 2:
        raise ValueError("the run does not cover the reference times")
    out = {"samples": int(keep.sum()), "columns": []}
    errors = []
    for s, r in zip(sim_cols, ref_cols):
        e = np.interp(t_ref[keep], t_sim, s) - r[keep]
        errors.append(e)
        out["columns"].append({"rmse": float(np.sqrt(np.mean(e * e))),
                               "abs_mean_error": float(abs(np.mean(e)))})
    if len(errors) >= 2:
        out["mde"] = float(np.mean(np.hypot(errors[0], errors[1])))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("reference")
    ap.add_argument("--columns", nargs="+", required=True,
                    help="column names in the run CSV, e.g. 'x [m]' 'y [m]'")
    ap.add_argument("--length", type=float, help="normalising length L [m] (positions)")
    ap.add_argument("--velocity", action="store_true",
                    help="normalise by sqrt(g h0) (velocities)")
    ap.add_argument("--h0", type=float, help="reference depth [m] for --velocity")
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--json", help="write the metrics to this file")
    a = ap.parse_args(argv)
    if a.velocity:
        if not a.h0:
            ap.error("--velocity needs --h0")
        scale = math.sqrt(a.g * a.h0)
    elif a.length:
        scale = a.length
    else:
        ap.error("give --length (positions) or --velocity --h0 (velocities)")
    header, sim = read_csv(a.run)
    _, ref = read_csv(a.reference)
    idx = []
    for c in a.columns:
        if c not in header:
            sys.exit(f"{a.run}: no column '{c}' (columns: {', '.join(header)})")
        idx.append(header.index(c))
    if ref.shape[1] < len(idx) + 1:
        sys.exit(f"{a.reference}: needs time plus {len(idx)} columns")
    m = compare(sim[:, 0], [sim[:, i] for i in idx], ref[:, 0],
                [ref[:, k + 1] for k in range(len(idx))])
    m["scale"] = scale
    for c, col in zip(a.columns, m["columns"]):
        col["name"] = c
        col["nrmse"] = col["rmse"] / scale
        print(f"{c:>16}: nRMSE {col['nrmse']:.4f}  RMSE {col['rmse']:.4g}  "
              f"|ME| {col['abs_mean_error']:.4g}")
    if "mde" in m:
        print(f"{'MDE':>16}: {m['mde']:.4g}")
    print(f"({m['samples']} reference samples, scale {scale:.4g})")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(m, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Checks tools/compare_track.py on series whose metrics are known in closed form."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

root = sys.argv[1]
tool = os.path.join(root, "tools", "compare_track.py")
with tempfile.TemporaryDirectory() as d:
    t = np.linspace(0, 2, 401)
    # simulation: x = t + 0.03 (constant offset), y = 0.04 sin(2 pi t) (zero mean over 2 periods)
    sim = np.column_stack([t, t + 0.03, 0.04 * np.sin(2 * np.pi * t)])
    np.savetxt(f"{d}/run.csv", sim, delimiter=",", header="time [s],x [m],y [m]", comments="")
    tr = np.linspace(0, 2, 201)
    ref = np.column_stack([tr, tr, np.zeros_like(tr)])
    np.savetxt(f"{d}/ref.csv", ref, delimiter=",", header="t,x,y", comments="")
    subprocess.run([sys.executable, tool, f"{d}/run.csv", f"{d}/ref.csv", "--columns", "x [m]",
                    "y [m]", "--length", "0.4", "--json", f"{d}/m.json"], check=True)
    m = json.load(open(f"{d}/m.json"))
    x, y = m["columns"]
    assert abs(x["rmse"] - 0.03) < 1e-9, x            # constant offset: RMSE = 0.03
    assert abs(x["nrmse"] - 0.075) < 1e-9, x          # / 0.4
    assert abs(x["abs_mean_error"] - 0.03) < 1e-9, x
    assert abs(y["rmse"] - 0.04 / np.sqrt(2)) < 2e-4, y  # RMS of a sine
    assert y["abs_mean_error"] < 1e-4, y
    # MDE = mean sqrt(0.03^2 + (0.04 sin)^2), computed independently
    s = 0.04 * np.sin(2 * np.pi * tr)
    assert abs(m["mde"] - np.mean(np.hypot(0.03, s))) < 1e-9, m
    r = subprocess.run([sys.executable, tool, f"{d}/run.csv", f"{d}/ref.csv", "--columns",
                        "vx [m/s]", "--velocity", "--h0", "0.4"], capture_output=True, text=True)
    assert r.returncode != 0 and "no column 'vx [m/s]'" in r.stderr, r.stderr
print("compare_track: OK")

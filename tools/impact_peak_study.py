#!/usr/bin/python3
"""How the impact peak at Lobovsky et al. (2014) sensor 1 depends on the sound speed c0, the
resolution dp, the wall treatment and the sampling window (issue #29).

    /usr/bin/python3 tools/impact_peak_study.py [--build build] [--out runs/impact_peaks]
        [--dp 0.0075,0.005] [--c0 10,20] [--wall dbc,mdbc] [--set key=value ...]

Runs the demo case (cases/dambreak2d.toml) to t = 0.6 s with sensor 1 sampled at 20 kHz (as
the experiment) for each combination, and prints a Markdown table of p/(rho g H): the peak of
the samples and the peaks of its 1, 5, 20 and 50 ms moving means (summary.json), beside the same
numbers of the experiment's event (Fig18_peak_event_5_sensors_5.dat: sensor 1).
"""
import argparse
import itertools
import json
import math
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REF = os.path.join(ROOT, "..", "shared", "reference", "dambreak_2d_lobovsky2014")
RHO_G_H = 1000 * 9.81 * 0.3
T_SCALE = math.sqrt(0.3 / 9.81)
WINDOWS = [0.001, 0.005, 0.02, 0.05]  # moving-mean windows [s], as summary.json's peak_mean_*


def window_peaks(t, p, windows):
    """Peak of the samples and of their moving means over each window (trapezoid rule)."""
    integral = [0.0]
    for k in range(1, len(t)):
        integral.append(integral[-1] + 0.5 * (t[k] - t[k - 1]) * (p[k] + p[k - 1]))
    out = [max(p)]
    for w in windows:
        best, j = -math.inf, 0
        for k in range(len(t)):
            if t[k] - w < t[0]:
                continue
            while t[j + 1] <= t[k] - w:
                j += 1
            f = (t[k] - w - t[j]) / (t[j + 1] - t[j])
            start = integral[j] + f * (integral[j + 1] - integral[j])
            best = max(best, (integral[k] - start) / w)
        out.append(best)
    return out


def experiment():
    t, p = [], []
    for line in open(os.path.join(REF, "Fig18_peak_event_5_sensors_5.dat")):
        if line.startswith("#") or not line.strip():
            continue
        a, b = map(float, line.split())
        t.append(a * T_SCALE)
        p.append(b)
    return window_peaks(t, p, WINDOWS), t[max(range(len(p)), key=p.__getitem__)] / T_SCALE


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "impact_peaks"))
    ap.add_argument("--dp", default="0.0075,0.005")
    ap.add_argument("--c0", default="10,20")
    ap.add_argument("--wall", default="dbc,mdbc")
    ap.add_argument("--set", action="append", default=[],
                    help="further case overrides, passed to every run")
    args = ap.parse_args()
    dps = [float(v) for v in args.dp.split(",")]
    c0s = [int(v) for v in args.c0.split(",")]
    exe = os.path.join(args.build, "debrisflow")
    rows = []
    extra = [a for kv in args.set for a in ("--set", kv)]
    for dp, c0, wall in itertools.product(dps, c0s, args.wall.split(",")):
        out = os.path.join(args.out, f"dp{dp}_c{c0}_{wall}")
        subprocess.run([exe, "run", os.path.join(ROOT, "cases", "dambreak2d.toml"), "--out", out,
                        "--overwrite", "--set", f"dp={dp}", "--set", "time.end=0.6",
                        "--set", f"sph.c0_coefficient={c0}", "--set", f'sph.boundary="{wall}"',
                        "--set", "probe.0.every=0.00005", "--set", "output.vtk=false"] + extra,
                       check=True, stdout=subprocess.DEVNULL)
        s = json.load(open(os.path.join(out, "summary.json")))["probes"]["sensor1"]["p [Pa]"]
        keys = ["peak"] + [f"peak_mean_{w * 1000:g}ms" for w in WINDOWS]
        rows.append((dp, c0, wall, [s[k] / RHO_G_H for k in keys], s["peak_time"] / T_SCALE))
    header = " | ".join(f"{w * 1000:g} ms mean" for w in WINDOWS)
    print(f"| dp (mm) | c0 / sqrt(g H) | wall | peak | {header} | T of peak |")
    print("|---|---|---|---|" + "---|" * len(WINDOWS) + "---|")
    for dp, c0, wall, peaks, tp in rows:
        cells = " | ".join(f"{v:.2f}" for v in peaks)
        print(f"| {dp * 1000:g} | {c0} | {wall} | {cells} | {tp:.2f} |")
    peaks, t_peak = experiment()
    cells = " | ".join(f"{v:.2f}" for v in peaks)
    print(f"| experiment (Fig. 18 event) | | | {cells} | {t_peak:.2f} |")


if __name__ == "__main__":
    main()

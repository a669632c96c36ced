#!/usr/bin/env python3
"""Flume run report (seed_experiments.md section E): section depth, velocity and Froude number
over the body of the surge, barrier peak and static loads, and plots.

usage: tools/flume_report.py RUN_DIR [--label NAME] [--figures DIR]

Surge body: the samples of the section probe with h >= 0.5 * (peak h); v, h, Fr, Savage are
their means. Barrier: peak of the 1 ms impulse-averaged normal force (Fn_avg) and the static
load, its mean over the last 10 % of the run. Paper values for comparison: F30-10 v 2.38 m/s,
h 0.024 m, Fr 7.15; F10-10 v 0.54, h 0.018, Fr 3.71; peak/static 11 (30 deg), 5 (10 deg).
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    # A run still in progress may have a partial last line.
    data = np.array([[float(x) for x in r] for r in rows[1:] if len(r) == len(head)])
    return head, data


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("--label", default=None)
    ap.add_argument("--figures", default=None)
    ap.add_argument("--cos", default=None, help="cos(slope) for Fr_dense (0.866 at 30 deg)")
    a = ap.parse_args()
    label = a.label or os.path.basename(os.path.normpath(a.run))
    probes = os.path.join(a.run, "probes")
    out = {}
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.6))
    sec = os.path.join(probes, "section.csv")
    if os.path.exists(sec):
        _, d = read(sec)
        t, h, v, fr, sav = d[:, 0], d[:, 1], d[:, 2], d[:, 4], d[:, 5]
        body = h >= 0.5 * h.max()
        out.update(v=v[body].mean(), h=h[body].mean(), Fr=fr[body].mean(), Savage=sav[body].mean(),
                   body_from=t[body].min(), body_to=t[body].max())
        if d.shape[1] > 7:
            # Depth of a dense flow at the paper's initial bulk density (1611 kg/m3 for 10 mm
            # glass, solid fraction 1611/2550) and the Froude number with it.
            hd = d[:, 7][body] / (1611 / 2550)
            cos_t = float(a.cos) if a.cos else 1.0
            out.update(h_dense=hd.mean(), Fr_dense=(v[body] / np.sqrt(9.81 * hd * cos_t)).mean())
        axes[0].plot(t, v, label="v [m/s]")
        axes[0].plot(t, 100 * h, label="h [cm]")
        axes[0].axvspan(t[body].min(), t[body].max(), color="0.9")
        axes[0].set_xlabel("t [s]")
        axes[0].set_title(f"{label}: section")
        axes[0].legend()
    bar = os.path.join(probes, "barrier_force.csv")
    if os.path.exists(bar):
        head, d = read(bar)
        t, fn, avg = d[:, 0], d[:, head.index("Fn [N]")], d[:, head.index("Fn_avg [N]")]
        static = avg[t >= t[-1] - 0.1 * (t[-1] - t[0])].mean()
        out.update(peak=avg.max(), peak_time=t[avg.argmax()], static=static,
                   ratio=avg.max() / static if static > 0 else float("nan"),
                   peak_instantaneous=fn.max())
        axes[1].plot(t, avg, label="Fn, 1 ms average [N]")
        axes[1].axhline(static, color="k", lw=0.8, ls="--", label="static")
        axes[1].set_xlabel("t [s]")
        axes[1].set_title(f"{label}: barrier force")
        axes[1].legend()
    for k, x in out.items():
        print(f"{k} = {x:.4g}")
    if a.figures:
        os.makedirs(a.figures, exist_ok=True)
        fig.tight_layout()
        fig.savefig(os.path.join(a.figures, f"{label}.png"), dpi=110)


if __name__ == "__main__":
    main()

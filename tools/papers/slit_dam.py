"""Section B of ../shared/reference/seed_experiments.md, two-level DEM slit dam (one 5 cm slit,
30 degree flume): discharge through the slit for Type A (fine grains only) and Type B (fine
grains + 4 cm boulders). Runs are named B_slitA_sd<n> and B_slitB_sd<n>_<k>b."""
import glob
import os
import re

import numpy as np

from common import (column, grain_mass, read_probe, running_mean, save_figure, status, table,
                    wall_seconds)
from vtk_series import frames, read_vtu

PEAK_TIME = 0.85  # s, discharge peak of every Type A case in the paper
SMOOTH = 0.1  # s, running mean of the discharge
DAM_EXIT = 1.24  # x of the dam's downstream face [m] (cases/papers/slit_dam_dem/*.toml)
NAME = re.compile(r"B_slit([AB])_sd(\d+)(?:_(\d+)b)?$")


def boulders_through(run):
    """(t, number of 4 cm boulders that have passed the dam) from the grain frames: all
    boulders of the first frame minus those still upstream of the dam's downstream face (the
    outlet removes the ones that reach the end of the flume)."""
    out, total = [], None
    for t, path in frames(run, "grains"):
        f = read_vtu(path)
        big = f["radius"] > 0.015
        if total is None:
            total = int(np.count_nonzero(big))
        out.append((t, total - int(np.count_nonzero(f["points"][big, 0] <= DAM_EXIT))))
    return out


def analyse(run):
    q = read_probe(run, "slit_discharge")
    if not q:
        return None
    t, m = q["time [s]"], column(q, "solid [kg/s]")
    ms = running_mean(t, m, SMOOTH)  # the grain-count noise out
    k, ks = int(np.argmax(m)), int(np.argmax(ms))
    trap = read_probe(run, "trapping")
    e = column(trap, "E")[-1] if trap else float("nan")
    passed = column(q, "solid_cumulative")[-1]
    # time after the peak at which the rate first falls to half the peak
    after = np.nonzero((t > t[k]) & (m < 0.5 * m[k]))[0]
    return dict(t=t, q=m, qs=ms, peak=m[k], t_peak=t[k], peak_s=ms[ks], t_peak_s=t[ks],
                passed=passed, E=e,
                half=t[after[0]] if len(after) else float("nan"), end=t[-1])


def size_effect(curves):
    """The paper's grain-size effect on the Type A peak: finer grains than SD5 peak higher (1 cm
    grains ~50 % below 0.125-0.167 cm ones; no effect beyond s/d = 30). Ratio of each finer
    Type A run's peak to A-SD5's, raw and 0.1 s mean, up to the shorter run's end."""
    if "A-SD5" not in curves:
        return []
    base = curves["A-SD5"][0]
    rows = []
    for label, (a, _) in sorted(curves.items()):
        if not label.startswith("A-SD") or label == "A-SD5":
            continue
        end = min(a["end"], base["end"])
        ref = [np.max(base[k][base["t"] <= end]) for k in ("q", "qs")]
        own = [np.max(a[k][a["t"] <= end]) for k in ("q", "qs")]
        rows.append([label, f"{own[0]:.2f} / {ref[0]:.2f} = {own[0] / ref[0]:.2f}",
                     f"{own[1]:.2f} / {ref[1]:.2f} = {own[1] / ref[1]:.2f}", f"{end:.2f} s"])
    if not rows:
        return []
    return (["Grain-size effect: peak discharge of the finer Type A runs against A-SD5 over the "
             "same span (the paper: SD5 peaks ~50 % below SD30/SD40, i.e. their ratio is ~2, and "
             "the effect vanishes from s/d = 30):", ""]
            + table(["case", "peak / A-SD5 peak, raw [kg/s]", "same, 0.1 s mean [kg/s]",
                     "over 0 to"], rows) + [""])


def report(root, figures):
    lines = ["### Two-level DEM slit dam (section B)", ""]
    rows, curves = [], {}
    for run in sorted(glob.glob(os.path.join(root, "B_slit*"))):
        m = NAME.search(run)
        if not m or not os.path.isdir(run):
            continue
        label = f"{m.group(1)}-SD{m.group(2)}" + (f"-{m.group(3)}B" if m.group(3) else "")
        a = analyse(run)
        n, mass = grain_mass(run)
        if a is None:
            rows.append([label, f"{n} / {mass:.2f} kg", status(run)] + ["–"] * 5)
            continue
        b = boulders_through(run) if m.group(1) == "B" else []
        nb = f"{b[-1][1]} of {m.group(3)}" if b else "–"
        rows.append([label, f"{n} / {mass:.2f} kg", f"{wall_seconds(run):.0f} s ({a['end']:.2f} s)",
                     f"{a['peak']:.2f} ({a['peak_s']:.2f})",
                     f"{a['t_peak']:.2f} ({a['t_peak_s']:.2f}; paper 0.85, {a['t_peak_s'] - PEAK_TIME:+.2f} s)",
                     f"{a['passed']:.2f} ({a['passed'] / mass:.0%})", f"{a['E']:.2f}", nb])
        curves[label] = (a, b)
    lines += ["Discharge through the slit (plane 1 cm downstream of the dam), time from the "
              "release; E = trapping efficiency between x = 1.0 m and the plane; the paper's "
              "peak time in brackets:", ""]
    lines += table(["case", "grains / mass", "wall (simulated)", "peak [kg/s] (0.1 s mean)",
                    "peak time [s] (0.1 s mean)",
                    "passed [kg]", "E", "boulders through"], rows)
    lines.append("")
    lines += size_effect(curves)
    if figures and curves:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        for k, (label, (a, b)) in enumerate(sorted(curves.items())):
            ax[0].plot(a["t"], a["qs"], lw=1, c=f"C{k}", label=label)
            if b:
                ax[1].step([x[0] for x in b], [x[1] for x in b], where="post", c=f"C{k}",
                           label=label)
        ax[0].axvline(PEAK_TIME, ls="--", c="k", lw=0.8, label="paper's peak time")
        ax[0].set(xlabel="t [s]", ylabel="discharge through the slit, 0.1 s mean [kg/s]")
        ax[1].set(xlabel="t [s]", ylabel="boulders through the slit (cumulative)")
        lines += save_figure(fig, ax, figures, "slit_dam_discharge.png", "slit discharge")
    return lines

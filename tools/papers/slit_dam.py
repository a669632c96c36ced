"""Section B of ../shared/reference/seed_experiments.md, two-level DEM slit dam (one 5 cm slit,
30 degree flume): discharge through the slit for Type A (fine grains only) and Type B (fine
grains + 4 cm boulders). Runs are named B_slitA_sd<n> and B_slitB_sd<n>_<k>b; a suffix
_seed<k> marks another realization (another random packing of the same grains) and _n<count>
another grain count (A-SD5(2): the paper's second SD5 case, 10,697 grains)."""
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
NAME = re.compile(r"B_slit([AB])_sd(\d+)(?:_(\d+)b)?(?:_seed(\d+)|_n(\d+))?$")
SECOND_COUNT = {5: 10697}  # grain count of the paper's A-SDn(2) cases


def label_of(m):
    """A-SD5, A-SD5 seed 2, A-SD5(2), B-SD5-16B from a NAME match."""
    label = f"{m.group(1)}-SD{m.group(2)}" + (f"-{m.group(3)}B" if m.group(3) else "")
    if m.group(5):
        second = SECOND_COUNT.get(int(m.group(2))) == int(m.group(5))
        label += "(2)" if second else f" n={m.group(5)}"
    if m.group(4):
        label += f" seed {m.group(4)}"
    return label


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


def peak_over(a, end):
    """Raw and 0.1 s mean peak of a run's discharge up to time end."""
    return [float(np.max(a[k][a["t"] <= end])) for k in ("q", "qs")]


def size_effect(curves):
    """The paper's grain-size effect on the Type A peak: finer grains than SD5 peak higher (1 cm
    grains ~50 % below 0.125-0.167 cm ones; no effect beyond s/d = 30). Ratio of each finer
    Type A run's peak to A-SD5's (the mean over its realizations of the paper's 12,393 grains,
    with the ratio's range over them), raw and 0.1 s mean, up to the shorter run's end."""
    sd5 = [a for label, (a, _) in curves.items()
           if label == "A-SD5" or re.fullmatch(r"A-SD5 seed \d+", label)]
    if not sd5:
        return []
    rows = []
    for label, (a, _) in sorted(curves.items()):
        if not re.fullmatch(r"A-SD\d+", label) or label == "A-SD5":
            continue
        end = min([a["end"]] + [b["end"] for b in sd5])
        ref = np.array([peak_over(b, end) for b in sd5])  # realizations x (raw, mean)
        own = peak_over(a, end)
        cells = []
        for k in range(2):
            mean = ref[:, k].mean()
            text = f"{own[k]:.2f} / {mean:.2f} = {own[k] / mean:.2f}"
            if len(sd5) > 1:
                text += f" ({own[k] / ref[:, k].max():.2f}–{own[k] / ref[:, k].min():.2f})"
            cells.append(text)
        rows.append([label] + cells + [f"{end:.2f} s", str(len(sd5))])
    if not rows:
        return []
    return (["Grain-size effect: peak discharge of the finer Type A runs against A-SD5 (mean "
             "over its realizations, the ratio's range over them in brackets) over the same span "
             "(the paper: SD5 peaks ~50 % below SD30/SD40, i.e. their ratio is ~2, and the effect "
             "vanishes from s/d = 30):", ""]
            + table(["case", "peak / A-SD5 peak, raw [kg/s]", "same, 0.1 s mean [kg/s]",
                     "over 0 to", "A-SD5 realizations"], rows) + [""])


def spread(curves):
    """Peak discharge and its time over the realizations of each Type A case (mean, sample
    standard deviation, range): how much the chaotic grain dynamics move them."""
    groups = {}
    for label, (a, _) in curves.items():
        groups.setdefault(re.sub(r" seed \d+$", "", label), []).append(a)
    rows = []
    for label, runs in sorted(groups.items()):
        if len(runs) < 2:
            continue
        end = min(a["end"] for a in runs)
        p = np.array([peak_over(a, end) for a in runs])
        ts = np.array([a["t_peak_s"] for a in runs])
        e = np.array([a["E"] for a in runs])
        rows.append([label, str(len(runs))]
                    + [f"{x.mean():.2f} ± {x.std(ddof=1):.2f} ({x.min():.2f}–{x.max():.2f})"
                       for x in (p[:, 0], p[:, 1], ts, e)])
    if not rows:
        return []
    return (["Spread over realizations (another random packing of the same grains; mean ± "
             "sample standard deviation, range in brackets):", ""]
            + table(["case", "runs", "peak, raw [kg/s]", "peak, 0.1 s mean [kg/s]",
                     "peak time, 0.1 s mean [s]", "E"], rows) + [""])


def report(root, figures):
    lines = ["### Two-level DEM slit dam (section B)", ""]
    rows, curves = [], {}
    for run in sorted(glob.glob(os.path.join(root, "B_slit*"))):
        m = NAME.search(run)
        if not m or not os.path.isdir(run):
            continue
        label = label_of(m)
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
    lines += spread(curves)
    lines += size_effect(curves)
    if figures and curves:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        main = sorted({re.sub(r" seed \d+$", "", label) for label in curves})
        for label, (a, b) in sorted(curves.items()):
            base = re.sub(r" seed \d+$", "", label)
            k = main.index(base)
            ax[0].plot(a["t"], a["qs"], lw=1 if base == label else 0.6, c=f"C{k}",
                       alpha=1 if base == label else 0.5,
                       label=label if base == label else None)
            if b:
                ax[1].step([x[0] for x in b], [x[1] for x in b], where="post", c=f"C{k}",
                           label=label)
        ax[0].axvline(PEAK_TIME, ls="--", c="k", lw=0.8, label="paper's peak time")
        ax[0].set(xlabel="t [s]", ylabel="discharge through the slit, 0.1 s mean [kg/s]")
        ax[1].set(xlabel="t [s]", ylabel="boulders through the slit (cumulative)")
        lines += save_figure(fig, ax, figures, "slit_dam_discharge.png", "slit discharge")
    return lines

"""Section E of ../shared/reference/seed_experiments.md: mono-disperse granular flow down a flume
at 10 and 30 degrees, free (section at 1.0-1.1 m) and against a rigid barrier at 1.2 m.
Runs are named E_<free|barrier><slope>_<2d|3d>_d<mm>, with the suffix _rr for the 2D discs with
rolling resistance (tools/papers/run_reduced.sh flume flume_rr)."""
import glob
import math
import os
import re

import numpy as np

from common import (column, grain_mass, pct, read_probe, running_mean, save_figure, status, table,
                    wall_seconds)

# test (slope, d mm): v, h, delta/h, shear rate, Fr, Savage (paper's free-flow table)
PAPER_FREE = {
    (10, 3): (0.19, 0.013, 0.23, 14.80, 4.86, 0.05),
    (10, 10): (0.54, 0.018, 0.55, 29.31, 3.71, 1.60),
    (10, 23): (1.01, 0.034, 0.68, 29.62, 3.07, 6.78),
    (10, 38): (1.44, 0.050, 0.76, 28.85, 2.49, 11.82),
    (30, 3): (2.37, 0.020, 0.15, 117.61, 7.99, 1.96),
    (30, 10): (2.38, 0.024, 0.43, 101.13, 7.15, 14.90),
    (30, 23): (2.51, 0.045, 0.51, 56.09, 4.60, 18.45),
    (30, 38): (2.53, 0.062, 0.62, 41.15, 3.75, 19.57),
}
# peak dynamic / static barrier load, read off the paper's text by delta/h (same order as d)
PAPER_RATIO = {(10, 3): 4, (10, 10): 5, (10, 23): 10, (10, 38): 14,
               (30, 3): 9, (30, 10): 11, (30, 23): 13, (30, 38): 15}
BULK = {3: 1620, 10: 1611, 23: 1583, 38: 1510}  # initial bulk density [kg/m3]
RHO_S = 2550.0
SMOOTH = 0.02  # s, running mean for the load-cell-like peak
NAME = re.compile(r"E_(free|barrier)(\d+)_(2d|3d)_d(\d+)(_rr)?$")
BARRIER_X = 1.2  # m downstream of the gate


def runs(root, rolling=False):
    """(free|barrier, slope, dim, d, path) of the runs of one grain model: round grains, or
    (rolling=True) the _rr runs with rolling resistance."""
    out = []
    for path in sorted(glob.glob(os.path.join(root, "E_*"))):
        m = NAME.search(path)
        if m and bool(m.group(5)) == rolling and os.path.exists(os.path.join(path, "case.toml")):
            out.append((m.group(1), int(m.group(2)), m.group(3), int(m.group(4)), path))
    return out


def deposit(run):
    """The deposit behind the barrier at the end of the run (runout probe along -x): its length
    from the barrier to its upstream end, and its height."""
    r = read_probe(run, "deposit")
    if not r:
        return None
    return dict(length=BARRIER_X - column(r, "front ")[-1], height=column(r, "height")[-1])


def surge(run, slope, d):
    """Means over the surge body (samples with h >= h_max / 2) at the section."""
    s = read_probe(run, "section")
    if not s or column(s, "h ").max() <= 0:
        return None
    t, h, v = s["time [s]"], column(s, "h "), column(s, "v ")
    body = h >= 0.5 * h.max()
    out = dict(v=v[body].mean(), h=h[body].mean(), Fr=column(s, "Fr")[body].mean(),
               Savage=column(s, "N_savage")[body].mean(), t0=t[body].min(), t1=t[body].max())
    if "h_solid [m]" in s or "col7" in s:
        hs = s.get("h_solid [m]", s.get("col7"))
        hd = hs[body] / (BULK[d] / RHO_S)  # dense depth at the paper's bulk density
        cos_t = math.cos(math.radians(slope))
        out["h_dense"] = hd.mean()
        out["Fr_dense"] = (v[body] / np.sqrt(9.81 * np.maximum(hd, 1e-9) * cos_t)).mean()
    return out


def barrier(run):
    """Peak of the 1 ms impulse-averaged barrier load and the static load (mean of the last
    10 % of the record)."""
    b = read_probe(run, "barrier_force")
    if not b:
        return None
    t, f = b["time [s]"], column(b, "Fn_avg")
    k = int(np.argmax(f))
    tail = f[int(0.9 * len(f)):]
    # 20 ms running mean: what a load cell of ~50 Hz bandwidth would read
    smooth = running_mean(t, f, SMOOTH)
    return dict(t=t, f=f, peak=f[k], t_peak=t[k], static=tail.mean(), end=t[-1],
                smooth=smooth, peak_smooth=smooth.max())


def deposit_text(run):
    dep = deposit(run)
    return "–" if dep is None else f"{dep['length']:.3f} / {dep['height']:.3f}"


def rolling_table(root):
    """Round discs against discs with rolling resistance (2D), test by test, where both ran."""
    rr = {(k, s, d): run for k, s, dim, d, run in runs(root, rolling=True) if dim == "2d"}
    plain = {(k, s, d): run for k, s, dim, d, run in runs(root) if dim == "2d"}
    rows = []
    for key in sorted(set(rr) & set(plain), key=lambda k: (k[0] != "free", k[1], k[2])):
        kind, slope, d = key
        for label, run in (("round discs", plain[key]), ("EPSD μ_r = 0.2", rr[key])):
            row = [f"{'F' if kind == 'free' else 'B'}{slope}-{d}", label,
                   f"{wall_seconds(run):.0f} s", status(run)]
            if kind == "free":
                p, sv = PAPER_FREE.get((slope, d)), surge(run, slope, d)
                row += ["–"] * 2 if sv is None else [
                    f"{sv['v']:.2f} ({pct(sv['v'], p[0])})",
                    f"{sv.get('h_dense', float('nan')):.3f} ({pct(sv.get('h_dense'), p[1])})"]
                row += ["–"] * 3
            else:
                b, ref = barrier(run), PAPER_RATIO.get((slope, d))
                wsin = grain_mass(run)[1] * 9.81 * math.sin(math.radians(slope))
                row += ["–", "–"]  # the free-flow columns
                if b is None:
                    row += ["–", "–"]
                else:
                    ratio = f"{b['peak'] / b['static']:.1f}" if b["static"] > 0 else "–"
                    row += [f"{b['peak']:.0f} / {b['static']:.1f} ({b['static'] / wsin:.2f} W sinθ)",
                            f"{ratio} ({ref})"]
                row.append(deposit_text(run))
            rows.append(row)
    if not rows:
        return []
    lines = ["Round discs against discs with rolling resistance (EPSD μ_r = 0.2 grain–grain and "
             "grain–flume, calibrated on glass-bead column collapses); free flow: surge speed and dense depth at the section (paper's error); barrier: "
             "peak (1 ms) / static load, peak / static (paper's ratio), the deposit at the "
             "end:", ""]
    lines += table(["test", "grains", "wall", "status", "v [m/s]", "h dense [m]",
                    "peak / static [N]", "peak / static", "deposit length / height [m]"], rows)
    return lines + [""]


def report(root, figures):
    lines = ["### Granular flow against a rigid barrier (section E)", ""]
    found = runs(root)
    if not found:
        return lines + ["(no runs)", ""]
    free = [r for r in found if r[0] == "free"]
    rows = []
    for _, slope, dim, d, run in sorted(free, key=lambda r: (r[2], r[1], r[3])):
        p = PAPER_FREE.get((slope, d))
        s = surge(run, slope, d)
        n, m = grain_mass(run)
        if s is None:
            rows.append([f"F{slope}-{d}", dim, f"{n} / {m:.1f} kg", status(run)] + ["–"] * 8)
            continue
        fr_paper = p[0] / math.sqrt(9.81 * p[1] * math.cos(math.radians(slope)))
        rows.append([f"F{slope}-{d}", dim, f"{n} / {m:.1f} kg", f"{wall_seconds(run):.0f} s",
                     f"{s['v']:.2f} ({p[0]}, {pct(s['v'], p[0])})",
                     f"{s['h']:.3f} ({p[1]})", f"{s.get('h_dense', float('nan')):.3f} ({pct(s.get('h_dense'), p[1])})",
                     f"{d / 1000 / s['h']:.2f} ({p[2]})",
                     f"{s['v'] / s['h']:.0f} ({p[3]:.0f})",
                     f"{s['Fr']:.2f} ({p[4]}; {fr_paper:.2f})", f"{s.get('Fr_dense', float('nan')):.2f}",
                     f"{s['Savage']:.2f} ({p[5]})"])
    lines += ["Free flow, section 1.0–1.1 m downstream of the gate, means over the surge body "
              "(h ≥ h_max/2); paper's value in brackets (for Fr also v/√(g h cosθ) from the "
              "paper's own v and h, which its Fr column does not follow); h top = 95th "
              "percentile of grain tops, h dense = solid depth / the paper's solid fraction:", ""]
    lines += table(["test", "dim", "grains / mass", "wall", "v [m/s]", "h top [m]",
                    "h dense [m]", "δ/h", "γ̇ [1/s]", "Fr", "Fr dense", "Savage"], rows)
    lines.append("")
    bars = [r for r in found if r[0] == "barrier"]
    rows = []
    curves = {}
    for _, slope, dim, d, run in sorted(bars, key=lambda r: (r[2], r[1], r[3])):
        b = barrier(run)
        n, m = grain_mass(run)
        ref = PAPER_RATIO.get((slope, d))
        if b is None:
            rows.append([f"B{slope}-{d}", dim, f"{n} / {m:.1f} kg", status(run)] + ["–"] * 5 + [ref])
            continue
        ratio = b["peak"] / b["static"] if b["static"] > 0 else float("nan")
        wsin = m * 9.81 * math.sin(math.radians(slope))
        rows.append([f"B{slope}-{d}", dim, f"{n} / {m:.1f} kg",
                     f"{wall_seconds(run):.0f} s ({b['end']:.2f} s)",
                     f"{b['peak']:.1f} at {b['t_peak']:.3f} s", f"{b['static']:.1f} ({b['static'] / wsin:.2f} W sinθ)",
                     f"{ratio:.1f}", f"{b['peak_smooth'] / b['static']:.1f}" if b["static"] > 0 else "–",
                     deposit_text(run), f"{ref} ({pct(ratio, ref)})"])
        curves[(dim, slope, d)] = b
    lines += ["Barrier load, impulse average over 1 ms (`Fn_avg`); static = mean of the last "
              "10 % of the run; W sinθ = the released weight along the slope:", ""]
    lines += table(["test", "dim", "grains / mass", "wall (simulated)", "peak [N]", "static [N]",
                    "peak / static", "20 ms mean peak / static", "deposit length / height [m]",
                    "paper"], rows)
    lines.append("")
    lines += rolling_table(root)
    if figures and curves:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        for (dim, slope, d), b in sorted(curves.items()):
            a = ax[0 if slope == 10 else 1]
            ls = "-" if dim == "2d" else "--"
            a.plot(b["t"], b["smooth"], ls, lw=0.9, label=f"{dim} d = {d} mm")
        for a, s in zip(ax, (10, 30)):
            a.set(xlabel="t [s]", ylabel="barrier load, 20 ms running mean [N]", title=f"{s}° barrier")
        lines += save_figure(fig, ax, figures, "granular_barrier_force.png", "barrier load")
    return lines

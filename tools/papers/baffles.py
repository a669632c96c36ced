"""Section B of ../shared/reference/seed_experiments.md, SPH-DEM: viscous slurry and five 1 m
boulders against three staggered rows of baffles and a barrier, slurry viscosity 0.1, 1 and
5 m^2/s. Runs are named B_baffles_nu<nu> (boulders on the slurry's surface, the case) and
B_baffles_<placement>_nu<nu> for the other starting places (tools/papers/run_reduced.sh)."""
import glob
import os
import re

import numpy as np

from common import column, read_probe, save_figure, status, table, wall_seconds
from vtk_series import frames, read_vtu

REGIME = {0.1: "fluid front ahead of the boulders, jet-like run-up",
          1.0: "coherent bouldery front", 5.0: "boulders detach; pile-up and dead zone"}
BOULDERS = 5
# Where the boulders start (the run name's tag); the reference says only "placed upstream".
PLACEMENTS = {"": "on the slurry's surface at its front (the case)",
              "bed": "on the bed in the slurry's front part",
              "up": "on the bed behind the slurry",
              "ahead": "on the bed ahead of the slurry"}


def fronts(run):
    """(t, fluid front x, leading boulder x) per frame: the front is the 99.5th percentile of
    the fluid particles' x (a few splashed particles do not count)."""
    bx = {}
    for k in range(1, BOULDERS + 1):
        b = read_probe(run, f"boulder{k}")
        if b:
            bx[k] = (b["time [s]"], b["x [m]"])
    out = []
    for t, path in frames(run, "particles"):
        f = read_vtu(path)
        x = f["points"][f["type"] == 0, 0]
        if len(x) == 0:
            continue
        lead = max((np.interp(t, *bx[k]) for k in bx), default=float("nan"))
        out.append((t, float(np.percentile(x, 99.5)), lead))
    return out


def analyse(run):
    baf, bar = read_probe(run, "baffle_load"), read_probe(run, "barrier_load")
    if not baf or not bar:
        return None
    out = dict(t=baf["time [s]"], baffle=column(baf, "Fn_avg") / 1e3,
               tb=bar["time [s]"], barrier=column(bar, "Fn_avg") / 1e3,
               barrier_bodies=column(bar, "Fx_bodies") / 1e3,
               baffle_bodies=column(baf, "Fx_bodies") / 1e3, end=bar["time [s]"][-1])
    for key, tk in (("baffle", "t"), ("barrier", "tb")):
        k = int(np.argmax(out[key]))
        out[key + "_peak"], out[key + "_tpeak"] = out[key][k], out[tk][k]
        hit = np.nonzero(out[key] > 1.0)[0]
        out[key + "_arrive"] = out[tk][hit[0]] if len(hit) else float("nan")
    run_up = read_probe(run, "barrier_runup")
    out["runup"] = column(run_up, "runup").max() if run_up else float("nan")
    over = read_probe(run, "overtopping")
    out["overtopped"] = column(over, "fluid_volume")[-1] if over else float("nan")
    final = [read_probe(run, f"boulder{k}") for k in range(1, BOULDERS + 1)]
    out["boulders_x"] = [b["x [m]"][-1] for b in final if b]
    out["fronts"] = fronts(run)
    return out


def lead_gap(fr, x):
    """Fluid front minus leading boulder when the front passes x (positive: fluid ahead)."""
    for t, front, lead in fr:
        if front >= x:
            return t, front - lead
    return float("nan"), float("nan")


def boulders_lead(fr, after=1.0, before=20.5):
    """(t, largest lead of the first boulder over the slurry front) from t = after on, while
    the front is short of x = before (1 m before the barrier, which stops the front while
    boulders may go over it):
    positive when the boulders ran ahead of the slurry (detached), else the closest they came
    to its front."""
    rows = [(t, lead - front) for t, front, lead in fr if t >= after and front < before]
    if not rows:
        return float("nan"), float("nan")
    return max(rows, key=lambda r: r[1])


def runs(root):
    """{placement tag: {nu: (run dir, analysis or None)}} for the runs found under root."""
    out = {}
    for run in sorted(glob.glob(os.path.join(root, "B_baffles_*nu*"))):
        m = re.search(r"B_baffles_(?:([a-z]+)_)?nu([0-9.]+)$", run)
        if m and os.path.isdir(run) and (m.group(1) or "") in PLACEMENTS:
            out.setdefault(m.group(1) or "", {})[float(m.group(2))] = (run, analyse(run))
    return out


def report(root, figures):
    lines = ["### SPH-DEM bouldery flow against baffles (section B)", ""]
    found = runs(root)
    res = found.get("", {})
    rows = []
    for nu, (run, a) in sorted(res.items()):
        if a is None:
            rows.append([nu, status(run)] + ["–"] * 9)
            continue
        t12, gap12 = lead_gap(a["fronts"], 12.0)
        rows.append([nu, f"{wall_seconds(run):.0f} s ({a['end']:.1f} s)",
                     f"{gap12:+.1f} m at {t12:.1f} s",
                     f"{a['baffle_arrive']:.2f}", f"{a['baffle_peak']:.0f} at {a['baffle_tpeak']:.2f} s",
                     f"{a['barrier_peak']:.0f} at {a['barrier_tpeak']:.2f} s",
                     f"{a['baffle_bodies'].max():.0f} / {a['barrier_bodies'].max():.0f}",
                     f"{a['runup']:.2f}", f"{a['overtopped']:.1f}",
                     ", ".join(f"{x:.1f}" for x in sorted(a["boulders_x"])),
                     REGIME.get(nu, "")])
    lines += ["Loads are impulse averages over 0.01 s normal to the structure; "
              "\"front − boulder\" is the distance by which the slurry front leads the first "
              "boulder when the front passes x = 12 m (3 m before the first baffle row):", ""]
    lines += table(["ν [m²/s]", "wall (simulated)", "front − boulder", "baffles hit [s]",
                    "baffle load peak [kN]", "barrier load peak [kN]",
                    "boulders' peak on baffles / barrier [kN]",
                    "barrier run-up [m]", "over the barrier [m³]", "boulders' final x [m]",
                    "paper's regime"], rows)
    lines.append("")
    lines += placements(found)
    if figures and res:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 3, figsize=(15, 4))
        for nu, (run, a) in sorted(res.items()):
            if a is None:
                continue
            ax[0].plot(a["t"], a["baffle"], lw=1, label=f"ν = {nu}")
            ax[1].plot(a["tb"], a["barrier"], lw=1, label=f"ν = {nu}")
            fr = np.array(a["fronts"])
            if len(fr):
                p = ax[2].plot(fr[:, 0], fr[:, 1], lw=1, label=f"slurry front, ν = {nu}")
                ax[2].plot(fr[:, 0], fr[:, 2], "--", lw=1, c=p[0].get_color(), label="leading boulder")
        ax[0].set(xlabel="t [s]", ylabel="load on the baffles [kN]")
        ax[1].set(xlabel="t [s]", ylabel="load on the barrier [kN]")
        ax[2].set(xlabel="t [s]", ylabel="x [m]")
        lines += save_figure(fig, ax, figures, "baffles_loads.png", "baffle and barrier loads", 7)
        lines += regimes(res, figures)
    return lines


def placements(found):
    """Where the boulders start against what they do, per viscosity."""
    rows = []
    for tag, desc in PLACEMENTS.items():
        for nu, (run, a) in sorted(found.get(tag, {}).items()):
            if a is None:
                continue
            t12, gap12 = lead_gap(a["fronts"], 12.0)
            tl, ahead = boulders_lead(a["fronts"])
            rows.append([desc, nu, f"{gap12:+.1f} m", f"{ahead:+.1f} m at {tl:.1f} s",
                         f"{a['baffle_bodies'].max():.0f} / {a['barrier_bodies'].max():.0f}",
                         ", ".join(f"{x:.1f}" for x in sorted(a["boulders_x"])),
                         f"{a['runup']:.2f}", f"{a['overtopped']:.1f}"])
    if not rows:
        return []
    lines = ["Where the boulders start decides the regime. \"Boulders ahead\" is the largest lead "
             "of the first boulder over the slurry front from 1 s on, until the front is 1 m from "
             "the barrier (negative: the slurry led all the time, by at least that much):", ""]
    lines += table(["boulders start", "ν [m²/s]", "front − boulder at x = 12 m",
                    "boulders ahead", "boulders' peak on baffles / barrier [kN]",
                    "boulders' final x [m]", "barrier run-up [m]", "over the barrier [m³]"], rows)
    return lines + [""]


def regimes(res, figures):
    """Side views (x-z) of slurry (all particles, coloured by speed) and boulders for each
    viscosity at three times; walls shown in the mid-channel slice 2.6 < y < 3.4."""
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle
    times = (2.0, 3.5, 6.0)
    nus = [nu for nu in sorted(res) if res[nu][1] is not None]
    if not nus:
        return []
    fig, ax = plt.subplots(len(nus), len(times), figsize=(16, 2.3 * len(nus)), squeeze=False)
    sc = None
    for i, nu in enumerate(nus):
        run = res[nu][0]
        fl = frames(run, "particles")
        tracks = [read_probe(run, f"boulder{k}") for k in range(1, BOULDERS + 1)]
        for j, t in enumerate(times):
            a = ax[i][j]
            if not fl:
                continue
            tf, path = min(fl, key=lambda f: abs(f[0] - t))
            f = read_vtu(path)
            p, v = f["points"], np.linalg.norm(f["velocity"], axis=1)
            fluid = f["type"] == 0
            mid = ~fluid & (f["group"] >= 0) & (p[:, 1] > 2.6) & (p[:, 1] < 3.4)
            a.scatter(p[mid, 0], p[mid, 2], s=0.3, c="0.7")
            sc = a.scatter(p[fluid, 0], p[fluid, 2], s=0.6, c=v[fluid], cmap="viridis", vmin=0,
                           vmax=12)
            for b in tracks:
                if b:
                    x, z = (np.interp(tf, b["time [s]"], b[k]) for k in ("x [m]", "z [m]"))
                    a.add_patch(Circle((x, z), 0.5, fc="none", ec="r", lw=1))
            a.set(xlim=(0, 30.5), ylim=(-0.5, 7.5), aspect="equal",
                  title=f"ν = {nu} m²/s, t = {tf:.1f} s")
            if j == 0:
                a.set_ylabel("z (normal to the bed) [m]")
            if i == len(nus) - 1:
                a.set_xlabel("x along the channel [m]")
    if sc is not None:
        fig.colorbar(sc, ax=ax.ravel().tolist(), label="|v| [m/s]", shrink=0.6)
    path = os.path.join(figures, "baffles_regimes.png")
    fig.savefig(path, dpi=90)
    return [f"![regimes](img/{os.path.basename(path)})", ""]

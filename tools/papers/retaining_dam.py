#!/usr/bin/python3
"""Retaining-dam case (section D of ../shared/reference/seed_experiments.md): peaks of the
crest mid-point displacement and of the debris impact force for the dam-groove slopes, beside
the paper's numbers and Kwan's formula, and a figure of the histories. Runs are named
D_dam<slope> (`debrisflow run cases/papers/retaining_dam.toml --set structure.0.slope_deg=B`).

Kwan's formula (Kwan 2012, GEO Report 270): F = kappa rho v^2 h w sin(beta) with
kappa = 2.5, w the gully width, rho the debris bulk density (slurry + rocks over the slurry
volume), and v, h the largest approach-flow momentum flux rho v^2 h seen by the `approach`
probe before the front reaches the dam.
"""
import glob
import math
import os

from common import grain_mass, pct, read_probe, save_figure, table, wall_seconds

PAPER = {  # slope: (crest peak mm, peak force kN, Kwan kN) from seed_experiments.md section D
    20: (None, 3032, 3618),
    30: (2.75, 5626, 6452),
    40: (3.55, 6917, 7728),
    50: (5.61, 9124, 9896),
}
WIDTH = 6.0  # gully width [m] (cases/papers/retaining_dam.toml)
KAPPA = 2.5


def slope_of(run):
    with open(os.path.join(run, "case.toml")) as f:
        text = f.read()
    for line in text.splitlines():
        if line.strip().startswith("slope_deg"):
            return float(line.split("=")[1].split("#")[0])
    raise SystemExit(f"{run}: no slope_deg in case.toml")


def bulk_density(run):
    """Slurry (96 m^3 at 1000 kg/m^3) plus the run's rocks (mass from its log), over 96 m^3."""
    return 1000.0 + grain_mass(run)[1] / 96.0


def analyse(run):
    beta = slope_of(run)
    load = {k: list(v) for k, v in read_probe(run, "dam_load").items()}
    crest = {k: list(v) for k, v in read_probe(run, "crest").items()}
    appr = {k: list(v) for k, v in read_probe(run, "approach").items()}
    t = load["time [s]"]
    fx = load["Fx_total [N]"]
    fg = load["Fx_grains [N]"]
    ff = load["Fx_fluid [N]"]
    # arrival: first time the debris load exceeds 1 kN
    arrive = next((ti for ti, f in zip(t, fx) if abs(f) > 1e3), None)
    k = max(range(len(fx)), key=lambda i: fx[i])
    # crest displacement relative to the self-weight state just before arrival
    tc, ux = crest["time [s]"], crest["ux [m]"]
    base = ux[max(i for i, ti in enumerate(tc) if arrive is None or ti <= arrive)]
    du = [u - base for u in ux]
    after = [i for i, ti in enumerate(tc) if arrive is not None and ti >= arrive] or [0]
    kc = max(after, key=lambda i: abs(du[i]))
    rho = bulk_density(run)
    flux = [(rho * v * v * h, v, h, fr) for ti, v, h, fr in
            zip(appr["time [s]"], appr["v [m/s]"], appr["h [m]"], appr["Fr [-]"])
            if arrive is None or ti <= arrive + 0.2]
    best = max(flux) if flux else (0, 0, 0, 0)
    kwan = KAPPA * best[0] * WIDTH * math.sin(math.radians(beta))
    return dict(beta=beta, t=t, fx=fx, fg=fg, ff=ff, tc=tc, du=du, arrive=arrive,
                f_peak=fx[k], t_peak=t[k], fg_peak=max(fg), ff_peak=max(ff),
                u_peak=du[kc], t_u=tc[kc], v=best[1], h=best[2], fr=best[3], kwan=kwan)


def report(root, figures):
    lines = ["### Retaining dam (section D)", ""]
    runs = sorted(glob.glob(os.path.join(root, "D_dam*")))
    ready = [r for r in runs if all(read_probe(r, n) for n in ("dam_load", "crest", "approach"))]
    res = [(r, analyse(r)) for r in ready if os.path.isdir(r)]
    rows = []
    for run, r in sorted(res, key=lambda x: x[1]["beta"]):
        p = PAPER.get(int(round(r["beta"])), (None, None, None))
        rows.append([f"{r['beta']:.0f}°", f"{wall_seconds(run):.0f} s ({r['t'][-1]:.1f} s)",
                     "–" if r["arrive"] is None else f"{r['arrive']:.2f} (2.1)",
                     f"{r['f_peak'] / 1e3:.0f} at {r['t_peak']:.2f} s",
                     f"{r['ff_peak'] / 1e3:.0f} / {r['fg_peak'] / 1e3:.0f}", p[1],
                     pct(r["f_peak"] / 1e3, p[1]),
                     f"{r['kwan'] / 1e3:.0f} (v {r['v']:.1f} m/s, h {r['h']:.2f} m)", p[2],
                     f"{1e3 * r['u_peak']:.4f} at {r['t_u']:.2f} s", p[0] if p[0] else "–"])
    lines += ["Peak load normal to the dam (fluid + rocks), Kwan's formula from our approach flow "
              "(κ = 2.5), crest mid-point displacement after arrival; the paper's numbers beside:", ""]
    lines += table(["groove slope", "wall (simulated)", "arrival [s] (paper)", "peak force [kN]",
                    "fluid / rocks peaks [kN]", "paper [kN]", "diff.", "Kwan, ours [kN]",
                    "Kwan, paper [kN]", "crest peak [mm]", "paper [mm]"], rows)
    lines.append("")
    if figures and res:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        for _, r in sorted(res, key=lambda x: x[1]["beta"]):
            ax[0].plot(r["t"], [f / 1e3 for f in r["fx"]], label=f"groove {r['beta']:.0f}°")
            ax[1].plot(r["tc"], [1e3 * u for u in r["du"]], label=f"groove {r['beta']:.0f}°")
        ax[0].set_xlabel("time [s]")
        ax[0].set_ylabel("impact force normal to the dam [kN]")
        ax[1].set_xlabel("time [s]")
        ax[1].set_ylabel("crest mid-point displacement [mm]")
        lines += save_figure(fig, ax, figures, "retaining_dam.png", "retaining dam")
    return lines

"""Section C of ../shared/reference/seed_experiments.md: a container carried by a dam-break
flood, 2D slice at the paper's dp (cases/papers/container_dambreak2d_reduced.toml). The paper's
nRMSE / |ME| / MDE need its experimental series (not available to us; tools/compare_track.py
computes them from any reference CSV): compared here are bore speed, gauges and the container's
start of motion and speed. Runs: C_container2d (dp = 10 mm) and C_container2d_dp5 (--set dp=0.005)."""
import os

import numpy as np

from common import column, read_probe, save_figure, status, table, wall_seconds

H0 = 0.4
PAPER = dict(bore_sph=2.53, bore_exp=2.46, bore_chanson=2.65)


def bore_speed(front, x0=2.6, x1=3.1):
    """Mean front speed between x0 and x1, the 0.5 m before the container's upstream face
    (3.125 m; WG3 at 3.2 m), and the arrival time at 3.2 m."""
    t, x = front["time [s]"], column(front, "x_front")
    i0, i1 = np.argmax(x >= x0), np.argmax(x >= x1)
    if x.max() < x1:
        return float("nan"), float("nan")
    return (x[i1] - x[i0]) / (t[i1] - t[i0]), t[np.argmax(x >= 3.2)]


RUNS = [("C_container2d", "dp = 10 mm"), ("C_container2d_dp5", "dp = 5 mm")]


def arrival(front, x):
    """First time the front reaches x, interpolated between samples (nan if it never does)."""
    t, xf = front["time [s]"], column(front, "x_front")
    k = np.argmax(xf >= x)
    if xf[k] < x:
        return float("nan")
    if k == 0:
        return float(t[0])
    f = (x - xf[k - 1]) / (xf[k] - xf[k - 1])
    return float(t[k - 1] + f * (t[k] - t[k - 1]))


def suite_checks(run):
    """The checks of tests/validation/rigid_container_test.cpp computed from a CLI run's
    probes (for runs with other settings than the suite's): the bore's arrival at the
    container's upstream face (x = 3.125 m), the container's largest |dx| until 0.05 s before
    it, its vx 0.25 s after it, its largest |dz|, and the front speed over 2.7-3.1 m."""
    c, f = read_probe(run, "container"), read_probe(run, "front")
    t_hit = arrival(f, 3.125)
    t, x, z, vx = c["time [s]"], c["x [m]"], c["z [m]"], c["vx [m/s]"]
    before = t < t_hit - 0.05
    after = t <= t_hit + 0.25
    return dict(t_hit=t_hit, moved_before=float(np.abs(x[before] - x[0]).max()) if before.any()
                else float("nan"), vx_after=float(vx[after][-1]) if after.any() else float("nan"),
                dz=float(np.abs(z - z[0]).max()),
                speed=0.4 / (arrival(f, 3.1) - arrival(f, 2.7)))


def measures(run):
    """The compared quantities of one run, or None when it has no probes."""
    c, f = read_probe(run, "container"), read_probe(run, "front")
    if not c or not f:
        return None
    speed, arrive = bore_speed(f)
    t, x, vx = c["time [s]"], c["x [m]"], c["vx [m/s]"]
    moving = np.nonzero(np.abs(x - x[0]) > 0.005)[0]
    start = t[moving[0]] if len(moving) else float("nan")
    late = (t >= start + 0.5) & (t <= start + 1.0)
    g = {k: read_probe(run, k) for k in ("WG1", "WG2", "WG3")}
    return dict(c=c, f=f, speed=speed, arrive=arrive, start=start,
                v_late=vx[late].mean() if late.any() else float("nan"), x_end=x[-1], t_end=t[-1],
                depth={k: column(v, "elevation")[-1] for k, v in g.items() if v})


def report(root, figures):
    lines = ["### Container in a dam-break flood (section C)", ""]
    found = [(name, label, measures(os.path.join(root, name))) for name, label in RUNS]
    found = [(n, l, m) for n, l, m in found if m]
    if not found:
        return lines + [f"{n}: {status(os.path.join(root, n))}" for n, _ in RUNS] + [""]
    for name, label, _ in found:
        run = os.path.join(root, name)
        lines.append(f"Run {name} ({label}): {wall_seconds(run):.0f} s wall, {status(run)}.")
    lines.append("")
    paper = f"{PAPER['bore_sph']} SPH / {PAPER['bore_exp']} exp. / {PAPER['bore_chanson']} Chanson"
    rows = [["bore front speed at WG3 [m/s] (2.6–3.1 m)"]
            + [f"{m['speed']:.2f} ({100 * (m['speed'] / PAPER['bore_exp'] - 1):+.0f} % vs exp.)"
               for _, _, m in found] + [paper],
            ["front arrival at x = 3.2 m [s]"] + [f"{m['arrive']:.2f}" for _, _, m in found] + ["–"],
            ["container starts moving [s]"] + [f"{m['start']:.2f}" for _, _, m in found]
            + ["when the bore arrives"],
            ["container speed 0.5–1 s later [m/s]"] + [f"{m['v_late']:.2f}" for _, _, m in found]
            + ["–"],
            ["container x at the end [m]"]
            + [f"{m['x_end']:.2f} (t = {m['t_end']:.1f} s)" for _, _, m in found] + ["–"]]
    for k in ("WG1", "WG2", "WG3"):
        rows.append([f"{k} water surface at the end [m]"]
                    + [f"{m['depth'][k]:.3f}" if k in m["depth"] else "–" for _, _, m in found]
                    + ["–"])
    lines += table(["quantity"] + [f"debrisflow 2D, {l}" for _, l, _ in found] + ["paper"], rows)
    lines.append("")
    if figures:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 3, figsize=(14, 4))
        for _, label, m in found:
            c, f = m["c"], m["f"]
            ax[0].plot(f["time [s]"], column(f, "x_front"), label=f"debrisflow 2D, {label}")
            ax[1].plot(c["time [s]"], c["x [m]"], label=label)
            ax[2].plot(c["time [s]"], c["vx [m/s]"], label=f"vx, {label}")
            ax[2].plot(c["time [s]"], c["vz [m/s]"], ":", label=f"vz, {label}")
        arrive = found[-1][2]["arrive"]
        tt = np.linspace(0, 3, 50)
        ax[0].plot(tt, 3.2 + PAPER["bore_exp"] * (tt - arrive), "--", lw=0.8,
                   label=f"2.46 m/s through the {found[-1][1]} arrival (exp. speed)")
        ax[0].axhline(3.2, ls=":", c="k", lw=0.8)
        ax[0].set(xlabel="t [s]", ylabel="front x [m]", ylim=(0, 7), title="bore front")
        ax[1].set(xlabel="t [s]", ylabel="container x [m]", title="trajectory")
        ax[2].set(xlabel="t [s]", ylabel="[m/s]", title="container velocity")
        lines += save_figure(fig, ax, figures, "container_dambreak2d.png", "container")
    return lines


if __name__ == "__main__":
    # python3 tools/papers/container.py RUN_DIR...: the suite's checks for each run.
    import sys
    for run in sys.argv[1:]:
        m = suite_checks(run)
        print(f"{run}: bore at the container {m['t_hit']:.3f} s; |dx| before {m['moved_before']:.2e} m "
              f"(tolerance 1e-3); vx 0.25 s later {m['vx_after']:.3f} m/s (> 0.1); |dz| {m['dz']:.2e} m "
              f"(< 2e-3); front speed 2.7-3.1 m {m['speed']:.3f} m/s (experiment 2.46)")

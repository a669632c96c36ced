"""Section C of ../shared/reference/seed_experiments.md: a container carried by a dam-break
flood, 2D slice at the paper's dp (cases/papers/container_dambreak2d_reduced.toml). The paper's
nRMSE / |ME| / MDE need its experimental series (not available to us; tools/compare_track.py
computes them from any reference CSV): compared here are bore speed, gauges and the container's
start of motion and speed. Run: C_container2d."""
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


def report(root, figures):
    run = os.path.join(root, "C_container2d")
    lines = ["### Container in a dam-break flood (section C)", ""]
    c, f = read_probe(run, "container"), read_probe(run, "front")
    if not c or not f:
        return lines + [f"C_container2d: {status(run)}", ""]
    speed, arrive = bore_speed(f)
    t, x, vx = c["time [s]"], c["x [m]"], c["vx [m/s]"]
    moving = np.nonzero(np.abs(x - x[0]) > 0.005)[0]
    start = t[moving[0]] if len(moving) else float("nan")
    late = (t >= start + 0.5) & (t <= start + 1.0)
    g = {k: read_probe(run, k) for k in ("WG1", "WG2", "WG3")}
    depth = {k: column(v, "elevation")[-1] for k, v in g.items() if v}
    rows = [["bore front speed at WG3 [m/s] (2.6–3.1 m)", f"{speed:.2f}",
             f"{PAPER['bore_sph']} SPH / {PAPER['bore_exp']} exp. / {PAPER['bore_chanson']} Chanson",
             f"{100 * (speed / PAPER['bore_exp'] - 1):+.0f} % vs exp."],
            ["front arrival at x = 3.2 m [s]", f"{arrive:.2f}", "–", ""],
            ["container starts moving [s]", f"{start:.2f}", "when the bore arrives", ""],
            ["container speed 0.5–1 s later [m/s]", f"{vx[late].mean():.2f}" if late.any() else "–", "–", ""],
            ["container x at the end [m]", f"{x[-1]:.2f} (t = {t[-1]:.1f} s)", "–", ""]]
    rows += [[f"{k} water surface at the end [m]", f"{d:.3f}", "–", ""] for k, d in depth.items()]
    lines += [f"Run: {wall_seconds(run):.0f} s wall, {status(run)}.", ""]
    lines += table(["quantity", "debrisflow 2D", "paper", "diff."], rows)
    lines.append("")
    if figures:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 3, figsize=(14, 4))
        ax[0].plot(f["time [s]"], column(f, "x_front"), label="debrisflow 2D")
        tt = np.linspace(0, 3, 50)
        ax[0].plot(tt, 3.2 + PAPER["bore_exp"] * (tt - arrive), "--", lw=0.8,
                   label="2.46 m/s through our arrival (exp. speed)")
        ax[0].axhline(3.2, ls=":", c="k", lw=0.8)
        ax[0].set(xlabel="t [s]", ylabel="front x [m]", ylim=(0, 7), title="bore front")
        ax[1].plot(t, x)
        ax[1].set(xlabel="t [s]", ylabel="container x [m]", title="trajectory")
        ax[2].plot(t, vx, label="vx")
        ax[2].plot(t, c["vz [m/s]"], label="vz")
        ax[2].set(xlabel="t [s]", ylabel="[m/s]", title="container velocity")
        lines += save_figure(fig, ax, figures, "container_dambreak2d.png", "container")
    return lines

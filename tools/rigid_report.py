#!/usr/bin/env python3
"""Figures of the rigid-body validation runs (docs/validation.md, "Rigid bodies").

  tools/rigid_report.py --tencate OUT_TENCATE --container OUT_CONTAINER \
      --floating OUT_FLOATING --figures docs/figures

Each OUT_* is the --out folder of the matching case (cases/rigid/tencate_E1.toml,
cases/papers/container_dambreak2d_reduced.toml, cases/rigid/floating_box2d.toml).
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

REF = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "reference")


def probe(out, name):
    return np.genfromtxt(os.path.join(out, "probes", name + ".csv"), delimiter=",",
                         names=True, invalid_raise=False)


def tencate(out, figures):
    s = probe(out, "sphere")
    d = 0.015
    gap = np.loadtxt(os.path.join(REF, "sedimentation_tencate2002", "tencate_Re1_5.csv"),
                     delimiter=",")
    u = np.loadtxt(os.path.join(REF, "sedimentation_tencate2002", "tencate_u_Re1_5.csv"),
                   delimiter=",")
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(s["time_s"], (s["z_m"] - d / 2) / d, label="debrisflow, dp = d/6")
    ax[0].plot(gap[:, 0], gap[:, 1], "o", label="ten Cate et al. 2002 (E1)")
    ax[0].set(xlabel="t [s]", ylabel="gap h/d", title="Sphere settling, Re = 1.5")
    ax[1].plot(s["time_s"], -s["vz_ms"], label="debrisflow, dp = d/6")
    ax[1].plot(u[:, 0], -u[:, 1], "o", label="ten Cate et al. 2002 (E1)")
    ax[1].axhline(0.038, ls="--", c="k", lw=0.8, label="measured terminal 0.038 m/s")
    ax[1].set(xlabel="t [s]", ylabel="settling velocity [m/s]")
    for a in ax:
        a.legend()
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "rigid_tencate_E1.png"), dpi=110)
    print("terminal velocity", float(-s["vz_ms"].min()))


def container(out, figures):
    c = probe(out, "container")
    f = probe(out, "front")
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    ax[0].plot(f["time_s"], f["x_front_m"])
    ax[0].axhline(3.2, ls="--", c="k", lw=0.8)
    ax[0].set(xlabel="t [s]", ylabel="front x [m]", title="Bore front (WG3 at 3.2 m)",
              ylim=(0, 7))
    ax[1].plot(c["time_s"], c["x_m"])
    ax[1].set(xlabel="t [s]", ylabel="container x [m]", title="Container trajectory")
    ax[2].plot(c["time_s"], c["vx_ms"], label="vx")
    ax[2].plot(c["time_s"], c["vz_ms"], label="vz")
    ax[2].set(xlabel="t [s]", ylabel="[m/s]", title="Container velocity")
    ax[2].legend()
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "rigid_container2d.png"), dpi=110)


def floating(out, figures):
    b = probe(out, "box")
    l = probe(out, "level")
    r = probe(out, "level_right")
    level = 0.5 * (np.interp(b["time_s"], l["time_s"], l["elevation_m"]) +
                   np.interp(b["time_s"], r["time_s"], r["elevation_m"]))
    draft = level - (b["z_m"] - 0.08)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(b["time_s"], draft * 1000, label="draft (mean water level - box bottom)")
    ax.axhline(80, ls="--", c="k", label="Archimedes 80 mm")
    ax.set(xlabel="t [s]", ylabel="draft [mm]", ylim=(70, 90), title="Floating box, dp = 10 mm")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "rigid_floating_box.png"), dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tencate")
    ap.add_argument("--container")
    ap.add_argument("--floating")
    ap.add_argument("--figures", default="docs/figures")
    a = ap.parse_args()
    os.makedirs(a.figures, exist_ok=True)
    if a.tencate:
        tencate(a.tencate, a.figures)
    if a.container:
        container(a.container, a.figures)
    if a.floating:
        floating(a.floating, a.figures)


if __name__ == "__main__":
    main()

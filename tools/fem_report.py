#!/usr/bin/env python3
"""Figure of the FEM fluid-structure validation run (docs/validation.md, "Deformable structures").

  /usr/bin/python3 tools/fem_report.py --gate OUT_GATE --figures docs/img

OUT_GATE is the --out folder of cases/fem/elastic_gate2d.toml (Antoci, Gallati & Sibilla 2007
setup). No digitised curve of the experiment is in ../shared/reference, so the figure shows our
free-end displacements with the cantilever relation uz = (3/5) ux^2 / L that the test checks.
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

GATE_LENGTH = 0.079  # [m]


def probe(out, name):
    return np.genfromtxt(os.path.join(out, "probes", name + ".csv"), delimiter=",",
                         names=True, invalid_raise=False)


def gate(out, figures):
    tip, load, level = probe(out, "gate_tip"), probe(out, "water_on_gate"), probe(out, "level")
    t, ux, uz = tip["time_s"], tip["ux_m"], tip["uz_m"]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    ax[0].plot(t, ux, label="ux (horizontal)")
    ax[0].plot(t, uz, label="uz (vertical)")
    ax[0].plot(t, 0.6 * ux ** 2 / GATE_LENGTH, "--", lw=0.8, label="(3/5) ux² / L")
    ax[0].set(xlabel="t [s]", ylabel="free-end displacement [m]", title="elastic gate, free end")
    ax[1].plot(load["time_s"], load[load.dtype.names[1]], label="Fx on the gate")
    ax[1].set(xlabel="t [s]", ylabel="[N/m]", title="water load on the gate")
    ax[2].plot(level["time_s"], level[level.dtype.names[1]], label="x = 0.05 m")
    ax[2].set(xlabel="t [s]", ylabel="water level [m]", title="reservoir level")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(figures, "elastic_gate.png")
    fig.savefig(path, dpi=110)
    i = int(np.argmax(ux))
    print(f"{path}: ux peak {ux[i]:.4f} m at {t[i]:.3f} s (uz {uz[i]:.4f} m); "
          f"ux at the end {ux[-1]:.4f} m (t = {t[-1]:.2f} s)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gate", required=True)
    ap.add_argument("--figures", default="docs/img")
    a = ap.parse_args()
    os.makedirs(a.figures, exist_ok=True)
    gate(a.gate, a.figures)


if __name__ == "__main__":
    main()

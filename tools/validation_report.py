#!/usr/bin/python3
"""Runs the 2D dam-break validation cases and writes plots and a results table.

    /usr/bin/python3 tools/validation_report.py [--build build] [--out runs/validation]

- Koshizuka & Oka at three resolutions (L/20, L/40, L/80): the resolution study;
- Martin & Moyce (square column) at a/40;
- Lobovsky et al. 2014 (the demo case) at dp = 6 mm to T = 6, sensor 1 pressure.
Figures go to docs/figures/, the table to docs/validation_results.md.
"""
import argparse
import csv
import math
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REF = os.path.join(ROOT, "..", "shared", "reference")
G = 9.81


def read_curve(path):
    rows = []
    for line in open(path):
        line = line.strip()
        if not line or line[0] == "#":
            continue
        parts = line.replace(",", " ").split()
        try:
            rows.append((float(parts[0]), float(parts[1])))
        except ValueError:
            continue
    return np.array(rows)


def read_probe(path):
    with open(path) as f:
        r = csv.reader(f)
        next(r)
        return np.array([[float(v) for v in row] for row in r])


def run(build, case, out, sets):
    cmd = [os.path.join(build, "debrisflow"), "run", case, "--out", out, "--overwrite", "--quiet",
           "--set", "output.vtk=false"]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    import json
    return json.load(open(os.path.join(out, "summary.json")))


def run_front(build, case, out, dp, t_scale, length):
    """Runs a dam-break case at dp; returns its summary and the front as (T, Z = x/length)."""
    s = run(build, os.path.join(ROOT, "cases", "validation", case), out, [f"dp={dp}"])
    f = read_probe(os.path.join(out, "probes", "front.csv"))
    return s, f[:, 0] / t_scale, (f[:, 1] + dp / 2) / length  # leading edge: centre + dp/2


def save_figure(xlabel, ylabel, title, xlim, path):
    plt.xlabel(xlabel)
    plt.ylabel(ylabel)
    plt.xlim(*xlim)
    plt.legend()
    plt.title(title)
    plt.tight_layout()
    plt.savefig(path, dpi=110)
    plt.close()


def front_errors(sim_T, sim_Z, ref, lo, hi):
    m = (ref[:, 0] >= lo) & (ref[:, 0] <= hi)
    z = np.interp(ref[m, 0], sim_T, sim_Z)
    return np.max(np.abs(z - ref[m, 1]) / ref[m, 1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "validation"))
    args = ap.parse_args()
    figs = os.path.join(ROOT, "docs", "figures")
    os.makedirs(figs, exist_ok=True)
    lines = ["| case | dp | particles | steps | wall s | result |", "|---|---|---|---|---|---|"]

    # Koshizuka & Oka resolution study
    L = 0.146
    ko_exp = read_curve(os.path.join(REF, "dambreak_2d_koshizuka_oka", "pysph_KO1996_exp.csv"))
    ko_mps = read_curve(os.path.join(REF, "dambreak_2d_koshizuka_oka", "pysph_KO1996_MPS_sim.csv"))
    plt.figure(figsize=(6, 4.5))
    plt.plot(ko_exp[:, 0], ko_exp[:, 1], "ko", label="experiment (Koshizuka & Oka 1996)")
    plt.plot(ko_mps[:, 0], ko_mps[:, 1], "k--", label="MPS (Koshizuka & Oka 1996)")
    for n in (20, 40, 80):
        s, T, Z = run_front(args.build, "dambreak_ko.toml", os.path.join(args.out, f"ko_L{n}"),
                            L / n, math.sqrt(L / (2 * G)), L)
        plt.plot(T, Z, label=f"debrisflow dp = L/{n}")
        e_mps = front_errors(T, Z, ko_mps, 1.0, 3.0)
        e_exp = front_errors(T, Z, ko_exp, 1.0, 3.2)
        lines.append(f"| Koshizuka & Oka front | L/{n} | {s['particles']['total']} | {s['steps']} "
                     f"| {s['wall_seconds']:.1f} | max error 1<=T<=3: {100*e_mps:.1f} % vs MPS, "
                     f"{100*e_exp:.1f} % vs experiment |")
    save_figure("T = t sqrt(2g/L)", "Z = z/L", "Dam-break surge front, resolution study",
                (0, 3.3), os.path.join(figs, "dambreak_ko_resolution.png"))

    # Martin & Moyce square column
    a = 0.1
    s, T, Z = run_front(args.build, "dambreak_mm.toml", os.path.join(args.out, "mm"), a / 40,
                        math.sqrt(a / G), a)
    mm = read_curve(os.path.join(REF, "dambreak_2d_martin_moyce",
                                 "MM1952_table_front_square_column.csv"))
    e = front_errors(T, Z, mm, 1.0, 3.0)
    lines.append(f"| Martin & Moyce front | a/40 | {s['particles']['total']} | {s['steps']} | "
                 f"{s['wall_seconds']:.1f} | max error 1<=T<=3: {100*e:.1f} % vs experiment |")
    plt.figure(figsize=(6, 4.5))
    plt.plot(mm[:, 0], mm[:, 1], "ko", label="experiment (Martin & Moyce 1952)")
    plt.plot(T, Z, label="debrisflow dp = a/40")
    save_figure("T = t sqrt(g/a)", "Z = z/a", "Dam-break surge front, square column", (0, 3.3),
                os.path.join(figs, "dambreak_mm.png"))

    # Lobovsky sensor 1
    H = 0.3
    out = os.path.join(args.out, "lobovsky")
    s = run(args.build, os.path.join(ROOT, "cases/dambreak2d.toml"), out,
            ["dp=0.006", f"time.end={6.1 * math.sqrt(H / G)}", "probe.0.every=0.0005"])
    exp = read_curve(os.path.join(REF, "dambreak_2d_lobovsky2014", "pysph_lobovsky_p1_y3mm.csv"))
    p = read_probe(os.path.join(out, "probes", "sensor1.csv"))
    T = p[:, 0] * math.sqrt(G / H)
    P = p[:, 1] / (1000 * G * H)
    arr_sim = T[np.argmax(P >= 0.5)]
    arr_exp = exp[np.argmax(exp[:, 1] >= 0.5), 0]
    ps = P[(T >= 3) & (T <= 6)].mean()
    pe = exp[(exp[:, 0] >= 3) & (exp[:, 0] <= 6), 1].mean()
    lines.append(f"| Lobovsky sensor 1 | 6 mm | {s['particles']['total']} | {s['steps']} | "
                 f"{s['wall_seconds']:.1f} | arrival T = {arr_sim:.3f} (exp. {arr_exp:.3f}); "
                 f"plateau 3<=T<=6 {ps:.3f} (exp. {pe:.3f}, {100*(ps-pe)/pe:+.1f} %) |")
    plt.figure(figsize=(6, 4.5))
    plt.plot(exp[:, 0], exp[:, 1], "ko", ms=3, label="experiment (Lobovsky et al. 2014)")
    plt.plot(T, P, lw=0.8, label="debrisflow dp = 6 mm")
    plt.ylim(-0.5, 4)  # the simulated impact spike (acoustic, ~20) is clipped
    save_figure("T = t sqrt(g/H)", "p / (rho g H)", "Pressure at sensor 1 (y = 3 mm)", (0, 7),
                os.path.join(figs, "dambreak_lobovsky_sensor1.png"))

    table = "\n".join(lines) + "\n"
    with open(os.path.join(ROOT, "docs", "validation_results.md"), "w") as fh:
        fh.write("<!-- written by tools/validation_report.py; do not edit -->\n" + table)
    print(table)


if __name__ == "__main__":
    main()

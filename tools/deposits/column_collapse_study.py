#!/usr/bin/env python3
"""Column-collapse deposits at several aspect ratios, for each deposit model.

Runs cases/deposits/column_collapse2d.toml (discs, no rolling resistance or EPSD),
column_collapse2d_clumps.toml (two-disc clumps) and column_collapse_channel3d.toml (3D spheres
between side walls 6 beads apart, or in a slab of that width periodic across the channel) with
the gate moved so that the settled column has the aspect ratio asked for, then reads the
`runout` probe: the column's width L0 and height H0 at t = 0 (the deposit's front and height), the run-out of the linked deposit
dL = front - L0 and its final height H at the end, and prints a Markdown table with the
published scalings beside it:
  quasi-2D channels, 3D beads (Lube et al. 2005; Lajeunesse et al. 2005):
      dL/L0 = 1.2 a (a < 1.8), 1.9 a^(2/3) (a > 2.8)
  true 2D, aluminium rods (Nguyen, Bui & Fukagawa 2015, arXiv:1512.05180):
      dL/L0 = 3.25 a^0.96 (0.65 <= a <= 1.5), 3.80 a^0.73 (a >= 1.5); H0/H = 1.42 a^(2/3)
      (a >= 0.65), H = H0 below.

usage: column_collapse_study.py BUILD/debrisflow OUTDIR [--threads N] [--aspects 0.5,1,2,4]
    [--count 800] [--seed S]
--count sets the grains per column (the column's width in grains, L0/d50, grows as its square
root: about 20 for 800 grains at a = 2), for the size effect of the deposit.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "..", "..", "cases", "deposits")

# grains per column: 800 discs (or 800 clumps of the same area-equivalent sizes); 2,800 spheres
# in the 3D channel (a column 20 beads long at a = 1, as the discs')
COUNT = 800
COUNT_3D = 2800
# settled solid fraction of the disc columns (measured: 0.77-0.78), to place the gate
PHI = 0.78
D50 = 0.005

# the 3D channel's width (its side walls 30 mm apart) and the settled solid fraction of its
# bead columns (measured: 0.557 at a = 1.15)
WIDTH = 0.03
PHI3 = 0.557
# the channel case with its side walls taken out and the slab periodic across the channel
PERIODIC = "periodic slab"

MODELS = {
    "discs, no rolling resistance": ("column_collapse2d.toml", ['dem.rolling="none"']),
    "discs, EPSD mu_r = 0.05": ("column_collapse2d.toml", ["material.0.rolling_friction=0.05"]),
    "discs, EPSD mu_r = 0.1": ("column_collapse2d.toml", ["material.0.rolling_friction=0.1"]),
    "discs, EPSD mu_r = 0.2": ("column_collapse2d.toml", []),
    "two-disc clumps, no rolling resistance": ("column_collapse2d_clumps.toml", []),
    "spheres between side walls 6 d apart, no rolling resistance": ("column_collapse_channel3d.toml", []),
    "spheres in a slab 6 d wide, periodic across, no rolling resistance": (PERIODIC, []),
}


def lube(a):
    if a < 1.8:
        return 1.2 * a
    if a > 2.8:
        return 1.9 * a ** (2 / 3)
    return None


def nguyen(a):
    if a < 0.65:
        return None
    return 3.25 * a**0.96 if a <= 1.5 else 3.80 * a**0.73


def nguyen_height(a):
    return 1.0 if a < 0.65 else 1 / (1.42 * a ** (2 / 3))


def periodic_slab(out):
    """The channel case without its side walls, periodic across the channel (written to out)."""
    with open(os.path.join(CASES, "column_collapse_channel3d.toml")) as f:
        text = f.read()
    blocks = text.split("\n\n")
    blocks = [b for b in blocks if 'name = "side_' not in b]
    text = "\n\n".join(blocks)
    text = text.replace("min = [-0.01, -0.005, -0.01]\nmax = [1.2, 0.035, 0.6]",
                        f"min = [-0.01, 0, -0.01]\nmax = [1.2, {WIDTH}, 0.6]\nperiodic = [\"y\"]", 1)
    path = out.rstrip("/") + ".toml"  # beside the run's folder, which --overwrite empties
    with open(path, "w") as f:
        f.write(text)
    return path


def run(exe, case, sets, out, threads):
    path = periodic_slab(out) if case == PERIODIC else os.path.join(CASES, case)
    cmd = [exe, "run", path, "--out", out, "--overwrite"]
    cmd += ["--threads", str(threads)]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed:\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    with open(os.path.join(out, "probes", "runout.csv")) as f:
        rows = [list(map(float, row)) for row in list(csv.reader(f))[1:]]
    return rows


def main():
    p = argparse.ArgumentParser()
    p.add_argument("exe")
    p.add_argument("out")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--aspects", default="0.5,1,2,4")
    p.add_argument("--end", type=float, default=3.0)
    p.add_argument("--only", default="", help="run the models whose name contains this")
    p.add_argument("--count", type=int, default=0,
                   help="grains (or clumps) per column (default 800 discs or clumps, 2,800 spheres)")
    p.add_argument("--seed", type=int, default=0, help="packing seed (0: the case's)")
    args = p.parse_args()
    aspects = [float(a) for a in args.aspects.split(",")]
    print("| grains | a = H0/L0 | L0 (m) | L0/d50 | dL/L0 linked | at t - 1 s | dL/L0 95 % mass | "
          "H/H0 | detached | quasi-2D 1.2a / 1.9a^(2/3) | true 2D rods | rods H/H0 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, (case, sets) in MODELS.items():
        if args.only not in name:
            continue
        spheres = "spheres" in name
        default_count = COUNT_3D if spheres else COUNT
        count = args.count or default_count
        # column area after settling (3D: its section across the channel; lognormal sizes,
        # sigma 0.1: a mean volume of pi d50^3 / 6 exp(4.5 sigma^2))
        if spheres:
            area = count * math.pi * D50**3 / 6 * math.exp(4.5 * 0.01) / PHI3 / WIDTH
        else:
            area = count * math.pi * D50**2 / 4 / PHI
        for a in aspects:
            L0 = math.sqrt(area / a)
            # room to insert the grains at random before settling (clumps by their bounding circles)
            box = (5.0 if "clumps" in case else 2.6) * area / L0
            # room for a run-out of twice the rods' scaling
            far = max(1.6, L0 * (1 + 2 * 3.8 * max(a, 1) ** 0.73))
            y_max = 0 if not spheres else WIDTH if case == PERIODIC else WIDTH + 0.005
            s = sets + [
                f"wall.2.point=[{L0:.5f},0,0]",
                f"grains.0.count={count}",
                f"grains.0.region.max=[{L0:.5f},{WIDTH if spheres else 0},{box:.4f}]",
                f"domain.max=[{far:.3f},{y_max},{box + 0.05:.4f}]",
                f"time.end={args.end}",
                "output.vtk_every=0.5",
            ] + ([f"grains.0.seed={args.seed}"] if args.seed else [])
            slug = "".join(c if c.isalnum() else "_" for c in name)
            tag = (f"_n{count}" if count != default_count else "") + (f"_s{args.seed}" if args.seed else "")
            out = os.path.join(args.out, f"{slug}_a{a:g}{tag}")
            rows = run(args.exe, case, s, out, args.threads)
            L, H = rows[0][1], rows[0][4]
            last = rows[-1]
            before = min(rows, key=lambda r: abs(r[0] - (last[0] - 1)))
            aa = H / L
            ref_l, ref_n = lube(aa), nguyen(aa)
            fmt = lambda v: "—" if v is None else f"{v:.2f}"
            print(f"| {name} | {aa:.2f} | {L:.3f} | {L / D50:.0f} | {(last[1] - L) / L:.2f} | "
                  f"{(before[1] - L) / L:.2f} | {(last[2] - L) / L:.2f} | {last[4] / H:.2f} | "
                  f"{int(last[5])} | {fmt(ref_l)} | {fmt(ref_n)} | {nguyen_height(aa):.2f} |",
                  flush=True)


if __name__ == "__main__":
    main()

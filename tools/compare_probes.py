#!/usr/bin/env python3
"""Largest difference between the probe files of two runs of one case (two backends, two builds).

For each probe and column (time excluded): max |a - b| over the rows / max |a| over the rows, the
largest printed per probe. Exit 1 when a probe's rows or times differ, or when the largest
difference exceeds --tolerance.

    tools/compare_probes.py RUN_A RUN_B [--tolerance 1e-8]
"""
import argparse
import pathlib
import sys

import numpy as np


def read(path):
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--tolerance", type=float, default=1e-8)
    args = ap.parse_args()
    worst = 0.0
    ok = True
    files = sorted(pathlib.Path(args.a, "probes").glob("*.csv"))
    if not files:
        sys.exit(f"{args.a}/probes holds no probe files")
    for fa in files:
        fb = pathlib.Path(args.b, "probes", fa.name)
        a, b = read(fa), read(fb)
        if a.shape != b.shape or not np.allclose(a[:, 0], b[:, 0], rtol=1e-9, atol=0):
            print(f"{fa.name}: rows or sample times differ ({a.shape} against {b.shape})")
            ok = False
            continue
        scale = np.maximum(np.abs(a[:, 1:]).max(axis=0), 1e-300)
        d = float((np.abs(a[:, 1:] - b[:, 1:]).max(axis=0) / scale).max()) if a.shape[1] > 1 else 0.0
        worst = max(worst, d)
        print(f"{fa.name}: {a.shape[0]} rows, largest scaled difference {d:.3e}")
    print(f"largest scaled difference {worst:.3e} (tolerance {args.tolerance:g})")
    sys.exit(0 if ok and worst <= args.tolerance else 1)


if __name__ == "__main__":
    main()

"""Frames of a debrisflow .pvd series: [(time, path)], and their particle arrays (read_vtu)."""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from read_vtu import read_vtu  # noqa: E402,F401  (tools/read_vtu.py)


def frames(run, series):
    """(time, file) of vtk/<series>.pvd, in time order ([] if the run wrote none)."""
    pvd = os.path.join(run, "vtk", series + ".pvd")
    if not os.path.exists(pvd):
        return []
    text = open(pvd).read()
    out = [(float(t), os.path.join(run, "vtk", f))
           for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]
    return [(t, f) for t, f in sorted(out) if os.path.exists(f)]

"""Reading run outputs for the paper reports: probe CSVs, summary.json, wall time, grain mass."""
import csv
import json
import os
import re

import numpy as np


def read_probe(run, name):
    """Columns of probes/<name>.csv by header name ({} if missing). Tolerates the partial last
    line of a run in progress; values beyond the header get the names col<i>."""
    path = os.path.join(run, "probes", name + ".csv")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        return {}
    head, width = rows[0], max(len(r) for r in rows[1:])
    head = head + [f"col{i}" for i in range(len(head), width)]
    data = np.array([[float(x) for x in r] for r in rows[1:] if len(r) == width])
    if data.size == 0:
        return {}
    return {h: data[:, i] for i, h in enumerate(head)}


def column(cols, prefix):
    """The first column whose name starts with prefix (units differ between 2D and 3D)."""
    for k, v in cols.items():
        if k.startswith(prefix):
            return v
    raise KeyError(prefix)


def summary(run):
    path = os.path.join(run, "summary.json")
    if not os.path.exists(path):
        return {}
    try:
        with open(path) as f:
            return json.load(f)
    except ValueError:
        return {}


def log_text(run):
    path = os.path.join(run, "log.txt")
    return open(path).read() if os.path.exists(path) else ""


def wall_seconds(run):
    """Wall time of the run (summary.json, or the last progress line of a run in progress)."""
    s = summary(run)
    if "wall_seconds" in s:
        return float(s["wall_seconds"])
    walls = re.findall(r"wall ([0-9.]+) s", log_text(run))
    return float(walls[-1]) if walls else float("nan")


def status(run):
    s = summary(run)
    if s.get("status"):
        return s["status"] + ("" if s["status"] == "completed" else f" at t = {s.get('simulated_time', 0):.2f} s")
    return "running or not run"


def grain_mass(run):
    """Total grain mass [kg] from the log line 'dem: N grains, M kg, ...'."""
    m = re.search(r"dem: (\d+) grains, ([0-9.]+(?:e[+-]?[0-9]+)?) kg", log_text(run))
    return (int(m.group(1)), float(m.group(2))) if m else (0, float("nan"))


def pct(value, ref):
    """Relative difference value/ref - 1 in percent, as text."""
    if ref is None or value is None or ref == 0 or not np.isfinite(value):
        return "–"
    return f"{100 * (value / ref - 1):+.0f} %"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return out


def running_mean(t, f, window):
    """Centred running mean of a uniformly sampled series f(t) over `window` seconds."""
    n = max(1, int(round(window / np.median(np.diff(t))))) if len(t) > 1 else 1
    return np.convolve(f, np.ones(n) / n, mode="same")


def save_figure(fig, axes, figures, name, alt, legend_size=8):
    """Legends and grids on every axis, then docs-ready PNG; returns the Markdown image line."""
    for a in np.ravel(axes):
        if a.get_legend_handles_labels()[0]:
            a.legend(fontsize=legend_size)
        a.grid(alpha=0.3)
    fig.tight_layout()
    path = os.path.join(figures, name)
    fig.savefig(path, dpi=110)
    return [f"![{alt}](img/{name})", ""]

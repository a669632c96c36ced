"""Section A of ../shared/reference/seed_experiments.md: trapping efficiency of a slit check dam
(P1 slits) for s/d95 = 1.18, 1.36, 1.49, reduced slice (cases/papers/slit_check_dam_reduced.toml).
E = 1 - M_down / M_up from the solid mass crossing a plane upstream and one just downstream of
the dam over the counting window (the `trapping` probe). Runs: A_check_s1.18, _s1.36, _s1.49."""
import os
import re

import numpy as np

from common import read_probe, save_figure, status, table, wall_seconds

RATIOS = (1.18, 1.36, 1.49)
E_EXP = 0.900  # experiment at s/d95 = 1.18
E_PAPER_RUNS = (0.786, 0.802, 0.810)  # the paper's SPH-DEM runs I/II/III at 1.18


def window(run):
    """The trapping probe's counting window [s] from the run's resolved case."""
    path = os.path.join(run, "case.toml")
    text = open(path).read() if os.path.exists(path) else ""
    m = re.search(r"window\s*=\s*\[\s*([0-9.eE+-]+)\s*,\s*([0-9.eE+-]+)\s*\]", text)
    return (float(m.group(1)), float(m.group(2))) if m else (float("nan"), float("nan"))


def analyse(run):
    """Final E and the masses counted over the window; None without a trapping probe."""
    tr = read_probe(run, "trapping")
    if not tr:
        return None
    a = dict(t=tr["time [s]"], E_t=tr["E [-]"], E=float(tr["E [-]"][-1]),
             up=float(tr["M_up [kg]"][-1]), down=float(tr["M_down [kg]"][-1]),
             window=window(run), t_end=float(tr["time [s]"][-1]))
    a["halves"] = half_window_E(tr["time [s]"], tr["M_up [kg]"], tr["M_down [kg]"],
                                a["window"][0], min(a["window"][1], a["t_end"]))
    return a


def half_window_E(t, up, down, t0, t1):
    """E over each half of the counting window, from the masses counted by each half's end:
    how much E moves with the sample (a few rocks pass the dam in a window)."""
    mid = 0.5 * (t0 + t1)
    at = lambda series, x: float(np.interp(x, t, series))
    out = []
    for a, b in ((t0, mid), (mid, t1)):
        d_up = at(up, b) - at(up, a)
        d_down = at(down, b) - at(down, a)
        out.append(1 - d_down / d_up if d_up > 0 else float("nan"))
    return out


CURRENT_TAGS = ("lag", "compact", "outlet")  # current physics besides the seeds
LONG_TAG = "w15"  # runs to 18 s counting E over 3-18 s, the paper's 15 s window (A_check_s<r>_w15*)


def is_long(tag):
    """A run counting over the paper's 15 s window, kept apart from the 3 s-window ensemble."""
    return tag.startswith(LONG_TAG)

# Realizations whose run folders are not kept (runs/ is not versioned; a fresh machine has
# none): E, the masses M_up / M_down [kg] where noted and the time the run reached, as their
# probes/trapping.csv gave them (docs/validation.md, section 4). A run found on disk under the
# same name replaces its record. Tags: "" the main run, seedN another hopper seed, lag / compact
# the lagged SPS stress / compacted pair list, side the earlier vertex-side contact rule.
RECORDED = [
    (1.18, "", 0.935, 4.21, 0.28, 6.0), (1.36, "", 0.766, 5.26, 1.23, 6.0),
    (1.49, "", 0.706, 5.35, 1.57, 6.0),
    (1.18, "seed2", 0.992, None, None, 6.0), (1.36, "seed2", 0.822, None, None, 6.0),
    (1.49, "seed2", 0.520, None, None, 6.0),
    (1.18, "lag", 0.932, 4.74, 0.32, 6.0), (1.36, "lag", 0.701, 5.51, 1.65, 6.0),
    (1.18, "compact", 0.939, 5.30, 0.32, 6.0),
    (1.18, "seed3", 0.595, 5.04, 2.04, 6.0), (1.36, "seed3", 0.899, None, 0.58, 6.0),
    (1.49, "seed3", 0.994, None, 0.04, 6.0),
    (1.49, "seed4", 0.752, None, 1.25, 6.0),
    (1.18, "side", 0.933, None, None, 6.0), (1.36, "side", 0.994, None, None, 6.0),
    # still with the catch basin (code before 807f884):
    (1.36, "seed5", 0.473, 4.98, 2.63, 6.0), (1.49, "seed5", 0.740, 5.84, 1.52, 6.0),
    # the outlet takes the rocks past the flume's end (807f884; seed 4 at 1.36 replaces the
    # basin run that stopped at 4.27 s):
    (1.18, "seed4", 0.859, 4.55, 0.64, 6.0), (1.36, "seed4", 1.000, 5.08, 0.00, 6.0),
    (1.18, "seed6", 1.000, 5.79, 0.00, 6.0), (1.49, "seed6", 0.676, 5.89, 1.91, 6.0),
    (1.36, "seed6", 0.759, 6.04, 1.45, 6.0), (1.49, "seed7", 0.663, 5.64, 1.90, 6.0),
    (1.18, "seed5", 0.961, 5.09, 0.20, 6.0), (1.36, "seed7", 0.827, 5.50, 0.95, 6.0),
    # to 18 s, E over the paper's 15 s window (3-18 s), seed 1 (`run_reduced.sh check15`):
    (1.18, "w15", 0.907, 16.21, 1.51, 18.0), (1.36, "w15", 0.806, 17.21, 3.33, 18.0),
    (1.49, "w15", 0.725, 20.46, 5.63, 18.0),
]


def recorded(entry):
    """A RECORDED entry as analyse() would give it (no time series)."""
    r, tag, e, up, down, t_end = entry
    nan = float("nan")
    return (r, tag, dict(E=e, up=nan if up is None else up, down=nan if down is None else down,
                         window=(3.0, 18.0) if is_long(tag) else (3.0, 6.0), t_end=t_end,
                         halves=[nan, nan], recorded=True))


def current_realizations(found, extra):
    """{s/d95: [E]} over the realizations of the current physics (main run, other hopper seeds,
    lagged SPS stress, compacted pair list) that counted their whole window (a run that
    stopped early is listed in the table but not averaged)."""
    current = {}
    for r, tag, a in [(r, "", a) for r, a in found.items()] + extra:
        whole = a["t_end"] >= a["window"][1] - 1e-6
        if whole and (tag == "" or tag in CURRENT_TAGS or tag.startswith("seed")):
            current.setdefault(r, []).append(a["E"])
    return current


def report(root, figures, records=()):
    """Tables and figures from the runs under root; `records` (e.g. RECORDED, with
    report.py --with-recorded) adds earlier runs' values, labelled as such in the table."""
    lines = ["### Slit check dam, trapping efficiency (section A)", ""]
    found = {r: analyse(os.path.join(root, f"A_check_s{r}")) for r in RATIOS}
    found = {r: a for r, a in found.items() if a is not None}
    # Further realizations of a width (A_check_s<r>_<tag>: another seed or an earlier code
    # whose trajectory diverged), listed and plotted beside the main run.
    extra = []
    for name in sorted(os.listdir(root)) if os.path.isdir(root) else []:
        m = re.fullmatch(r"A_check_s([0-9.]+)_(\w+)", name)
        if m and float(m.group(1)) in RATIOS:
            a = analyse(os.path.join(root, name))
            if a is not None:
                extra.append((float(m.group(1)), m.group(2), a))
    on_disk = {(r, "") for r in found} | {(r, tag) for r, tag, _ in extra}
    for r, tag, a in map(recorded, records):
        if (r, tag) in on_disk:
            continue
        if tag == "":
            found[r] = a
        else:
            extra.append((r, tag, a))
    if not found:
        return lines + ["A_check_s*: not run (`tools/papers/run_reduced.sh check`)", ""]
    rows = []
    runs = [(r, "", a) for r, a in found.items()] + extra
    for r, tag, a in sorted(runs, key=lambda e: (e[0], e[1])):
        run = os.path.join(root, f"A_check_s{r}" + (f"_{tag}" if tag else ""))
        paper = f"exp. {E_EXP}; runs {' / '.join(map(str, E_PAPER_RUNS))}" if r == 1.18 else \
            "below the 1.18 value"
        diff = f"{100 * (a['E'] / E_EXP - 1):+.0f} % vs exp." if r == 1.18 else ""
        w0, w1 = a["window"]
        mass = lambda x: "–" if np.isnan(x) else f"{x:.2f}"
        rows.append([f"{r}" + (f" ({tag})" if tag else ""), f"{a['E']:.3f}",
                     f"{mass(a['up'])} / {mass(a['down'])}",
                     f"{w0:g}–{round(min(w1, a['t_end']), 2):g}",
                     " / ".join(mass(e) for e in a["halves"]), paper, diff,
                     "recorded earlier, not in these runs" if a.get("recorded") else
                     f"{wall_seconds(run) / 60:.0f} min, {status(run)}"])
    lines += table(["s/d95", "E", "M_up / M_down [kg]", "window [s]",
                    "E, first / second half", "paper", "diff.", "run"], rows)
    lines.append("")
    current = current_realizations(found, extra)
    sem = lambda e: np.std(e, ddof=1) / np.sqrt(len(e))
    stats = [f"{r}: {np.mean(e):.3f} ± {np.std(e, ddof=1):.3f} (s.e. {sem(e):.3f}, {len(e)} runs)"
             for r, e in sorted(current.items()) if len(e) > 1]
    if stats:
        lines += ["Mean ± s.d. over the current code's realizations that counted their whole "
                  "window: " + "; ".join(stats) + ".", ""]
    # Is E lower at the widest slit? Welch's t of the difference of the means.
    lo, hi = RATIOS[0], RATIOS[-1]
    if len(current.get(lo, [])) > 1 and len(current.get(hi, [])) > 1:
        d = np.mean(current[lo]) - np.mean(current[hi])
        se = np.hypot(sem(current[lo]), sem(current[hi]))
        lines += [f"E({lo}) − E({hi}) = {d:.3f} ± {se:.3f} (Welch t = {d / se:.2f}).", ""]
    long = [(r, tag, a) for r, tag, a in sorted(extra, key=lambda e: (e[0], e[1]))
            if is_long(tag) and a["t_end"] > a["window"][0]]
    if long:
        lines += ["Over the paper's 15 s window: " + "; ".join(
            f"{r} ({tag}): E = {a['E']:.3f} over {a['window'][0]:g}–"
            f"{round(min(a['window'][1], a['t_end']), 2):g} s" for r, tag, a in long) + ".", ""]
    if figures:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        rs = sorted(found)
        ax[0].plot(rs, [found[r]["E"] for r in rs], "o-", label="debrisflow, reduced slice")
        short = [(r, a) for r, tag, a in extra if not is_long(tag)]
        if short:
            ax[0].plot([r for r, _ in short], [a["E"] for _, a in short], "o", mfc="none",
                       color="C0", label="other realizations (other seeds, earlier code)")
        if long:
            ax[0].plot([r - 0.005 for r, _, _ in long], [a["E"] for _, _, a in long], "*",
                       ms=12, color="C2", label="15 s window (3–18 s)")
        ms = [r for r in sorted(current) if len(current[r]) > 1]
        if ms:
            ax[0].errorbar([r + 0.005 for r in ms], [np.mean(current[r]) for r in ms],
                           yerr=[np.std(current[r], ddof=1) for r in ms], fmt="D", color="C1",
                           capsize=4, label="mean ± s.d. of the current code's realizations")
        ax[0].plot([1.18], [E_EXP], "ks", label="experiment")
        ax[0].plot([1.18] * 3, E_PAPER_RUNS, "r^", label="paper SPH-DEM runs I–III")
        ax[0].set(xlabel="s / d95", ylabel="trapping efficiency E", ylim=(0, 1.05),
                  title="E vs relative slit width (P1)")
        for r, tag, a in sorted(runs, key=lambda e: (e[0], e[1])):
            if a.get("recorded"):  # no time series kept
                continue
            inside = a["t"] >= a["window"][0]
            ax[1].plot(a["t"][inside], a["E_t"][inside], color=f"C{RATIOS.index(r)}",
                       lw=1, label=f"s/d95 = {r}" + (f" ({tag})" if tag else ""))
        ax[1].set(xlabel="t [s]", ylabel="E over the window so far", ylim=(0, 1.05),
                  title="running trapping efficiency")
        lines += save_figure(fig, ax, figures, "check_dam_trapping.png", "check dam trapping")
    return lines

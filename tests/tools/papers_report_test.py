#!/usr/bin/env python3
"""Checks tools/papers/report.py's analyses on synthetic run outputs with known answers: surge
means at the flume section, barrier peak / static, slit discharge peak and trapping, bore
speed of the container case, check-dam trapping efficiency and window, and that the whole report renders."""
import os
import subprocess
import sys
import tempfile

import numpy as np

root = sys.argv[1]
sys.path.insert(0, os.path.join(root, "tools", "papers"))
import baffles  # noqa: E402
import check_dam  # noqa: E402
import common  # noqa: E402
import container  # noqa: E402
import granular_flume  # noqa: E402
import slit_dam  # noqa: E402


def write(run, name, header, cols):
    os.makedirs(os.path.join(run, "probes"), exist_ok=True)
    open(os.path.join(run, "case.toml"), "a").close()
    np.savetxt(os.path.join(run, "probes", name + ".csv"), np.column_stack(cols), delimiter=",",
               header=",".join(header), comments="")


with tempfile.TemporaryDirectory() as d:
    t = np.linspace(0, 2, 2001)
    # Section: a surge with h = 0.02 m and v = 2 m/s between 0.5 and 1 s, a 1 mm tail elsewhere.
    body = (t >= 0.5) & (t <= 1.0)
    h = np.where(body, 0.02, 0.001)
    v = np.where(body, 2.0, 0.1)
    run = os.path.join(d, "E_free30_2d_d10")
    z = np.zeros_like(t)
    write(run, "section", ["time [s]", "h [m]", "v [m/s]", "rho_bulk [kg/m3]", "Fr [-]",
                           "N_savage [-]", "grains [-]", "h_solid [m]"],
          [t, h, v, z, v / np.sqrt(9.81 * h), z + 1.5, z + 10, h * 1611 / 2550])
    open(os.path.join(run, "log.txt"), "w").write("dem: 510 grains, 20.43 kg, 3 walls\n")
    s = granular_flume.surge(run, 30, 10)
    assert abs(s["v"] - 2.0) < 1e-12 and abs(s["h"] - 0.02) < 1e-12, s
    assert abs(s["t0"] - 0.5) < 1e-9 and abs(s["t1"] - 1.0) < 1e-9, s
    assert abs(s["h_dense"] - 0.02) < 1e-12, s  # h_solid at the paper's solid fraction
    fr = 2.0 / np.sqrt(9.81 * 0.02 * np.cos(np.radians(30)))
    assert abs(s["Fr_dense"] - fr) < 1e-9, s
    # Barrier: a triangular 50 N pulse on a 5 N static load reached at 1.5 s.
    run = os.path.join(d, "E_barrier30_2d_d10")
    f = np.where(t < 0.5, 0.0, 5.0) + 45.0 * np.maximum(0, 1 - np.abs(t - 0.6) / 0.05)
    write(run, "barrier_force", ["time [s]", "Fx [N]", "Fy [N]", "Fz [N]", "F [N]", "Fn [N]",
                                 "Fn_avg [N]"], [t, f, z, z, f, f, f])
    b = granular_flume.barrier(run)
    assert abs(b["peak"] - 50.0) < 1e-9 and abs(b["t_peak"] - 0.6) < 1e-9, b
    assert abs(b["static"] - 5.0) < 1e-12, b
    # Slit discharge: a Gaussian pulse peaking at 0.85 s; E = 0.25 at the end.
    run = os.path.join(d, "B_slitA_sd5")
    q = 10 * np.exp(-(((t - 0.85) / 0.1) ** 2))
    write(run, "slit_discharge", ["time [s]", "solid [kg/s]", "solid_Q [m3/s]",
                                  "solid_cumulative [kg]"], [t, q, q / 2650, np.cumsum(q) * 1e-3])
    write(run, "trapping", ["time [s]", "M_up [kg]", "M_down [kg]", "E [-]"],
          [t, z + 4, z + 3, z + 0.25])
    a = slit_dam.analyse(run)
    assert abs(a["t_peak"] - 0.85) < 1e-9 and abs(a["peak"] - 10) < 1e-9, a
    assert abs(a["E"] - 0.25) < 1e-12, a
    assert abs(a["passed"] - 10 * 0.1 * np.sqrt(np.pi)) < 0.02, a  # integral of the pulse
    # Realizations: run names map to labels, and the spread of two pulses of peak 10 and 12 is
    # 11 +- sqrt(2) with the ratio of a finer run taken against their mean.
    label = lambda name: slit_dam.label_of(slit_dam.NAME.search(name))
    assert label("B_slitA_sd5") == "A-SD5" and label("B_slitA_sd5_seed2") == "A-SD5 seed 2"
    assert label("B_slitA_sd5_n10697") == "A-SD5(2)" and label("B_slitB_sd5_16b") == "B-SD5-16B"
    b2 = dict(a, q=1.2 * a["q"], qs=1.2 * a["qs"])
    fine = dict(a, q=2.2 * a["q"], qs=2.2 * a["qs"])
    spread = "\n".join(slit_dam.spread({"A-SD5": (a, []), "A-SD5 seed 2": (b2, [])}))
    assert "11.00 ± 1.41 (10.00–12.00)" in spread, spread
    ratio = "\n".join(slit_dam.size_effect({"A-SD5": (a, []), "A-SD5 seed 2": (b2, []),
                                            "A-SD10": (fine, [])}))
    assert "22.00 / 11.00 = 2.00 (1.83–2.20)" in ratio, ratio
    # Container: a front moving at 2.5 m/s, at 3.2 m at t = 1.28 s.
    run = os.path.join(d, "C_container2d")
    write(run, "front", ["time [s]", "x_front [m]"], [t, 2.5 * t])
    speed, arrive = container.bore_speed(container.read_probe(run, "front"))
    assert abs(speed - 2.5) < 1e-6 and abs(arrive - 1.28) < 1e-3, (speed, arrive)
    # Check dam: 2 kg reach the upstream plane and 0.2 kg pass the dam over a 3-6 s window.
    run = os.path.join(d, "A_check_s1.18")
    t6 = np.linspace(0, 6, 601)
    up, down = 2 * np.clip(t6 - 3, 0, 3) / 3, 0.2 * np.clip(t6 - 3, 0, 3) / 3
    write(run, "trapping", ["time [s]", "M_up [kg]", "M_down [kg]", "E [-]"],
          [t6, up, down, 1 - down / np.maximum(up, 1e-12)])
    with open(os.path.join(run, "case.toml"), "w") as f:
        f.write('[[probe]]\nname = "trapping"\nwindow = [ 3.0, 6.0 ]\n')
    c = check_dam.analyse(run)
    assert abs(c["E"] - 0.9) < 1e-12 and abs(c["up"] - 2) < 1e-12, c
    assert c["window"] == (3.0, 6.0), c
    # Recorded realizations fill in for run folders not on disk; a folder replaces its record:
    # at 1.18 the run above (0.9) and a recorded seed 2 (0.7) give 0.8 +- 0.1414; the record
    # of the main run (0.1) is not used, and the stopped one (to 4.5 s) is not averaged.
    recs = [(1.18, "", 0.1, None, None, 6.0), (1.18, "seed2", 0.7, 1.0, 0.3, 6.0),
            (1.18, "seed3", 0.5, None, None, 4.5), (1.18, "w15", 0.85, 20.0, 3.0, 18.0)]
    text = "\n".join(check_dam.report(d, None, recs))
    assert "1.18: 0.800 ± 0.141 (s.e. 0.100, 2 runs)" in text, text  # w15 kept apart
    assert "15 s window: 1.18 (w15): E = 0.850 over 3–18 s" in text, text
    assert "| 1.18 (seed2) | 0.700 | 1.00 / 0.30 | 3–6 |" in text, text
    # Baffles: a slurry front at 2 m/s from x = 9 m and a boulder at 2.5 m/s from 8 m: the
    # front leads by 0.25 m when it passes 12 m (t = 1.5 s); the boulder is 1 m ahead at 4 s.
    tf = np.linspace(0, 4, 41)
    fr = list(zip(tf, 9 + 2 * tf, 8 + 2.5 * tf))
    tg, gap = baffles.lead_gap(fr, 12.0)
    assert abs(tg - 1.5) < 1e-9 and abs(gap - 0.25) < 1e-9, (tg, gap)
    tl, ahead = baffles.boulders_lead(fr)
    assert abs(tl - 4.0) < 1e-9 and abs(ahead - 1.0) < 1e-9, (tl, ahead)
    for name in ("B_baffles_nu0.1", "B_baffles_bed_nu5", "B_baffles_odd_nu1"):
        os.makedirs(os.path.join(d, name))
    found = baffles.runs(d)
    assert sorted(found) == ["", "bed"] and list(found["bed"]) == [5.0], found
    # Grain mass from the log line, in both of the engine's number formats.
    run = os.path.join(d, "D_dam40")
    os.makedirs(run)
    open(os.path.join(run, "log.txt"), "w").write("dem: 2160 grains, 8.092e+04 kg, 3 walls\n")
    assert common.grain_mass(run) == (2160, 80920.0), common.grain_mass(run)
    # The whole report renders with what is there (and without the other runs).
    out = subprocess.run([sys.executable, os.path.join(root, "tools", "papers", "report.py"), d],
                         check=True, capture_output=True, text=True).stdout
    assert "| F30-10 | 2d | 510 / 20.4 kg" in out, out
    assert "| B30-10 | 2d |" in out and "| 10.0 |" in out and "| 11 (-9 %) |" in out, out
    assert "| 1.18 | 0.900 | 2.00 / 0.20 | 3–6 |" in out and "+0 % vs exp." in out, out
    assert "recorded earlier" not in out, out  # only with --with-recorded
    # No runs: exit 2, no table filled from records, no figure.
    report = os.path.join(root, "tools", "papers", "report.py")
    for empty in (os.path.join(d, "no_such_folder"), os.path.join(d, "empty")):
        os.makedirs(os.path.join(d, "empty"), exist_ok=True)
        figs = os.path.join(d, "figs")
        r = subprocess.run([sys.executable, report, empty, "--figures", figs],
                           capture_output=True, text=True)
        assert r.returncode == 2 and "no runs" in r.stderr, (r.returncode, r.stdout, r.stderr)
        assert not os.path.exists(figs) and "0.935" not in r.stdout, r.stdout
print("papers report: OK")

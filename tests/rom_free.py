"""The reduced-order transient without contact (-rom, docs/performance.md "Reduced-order transient").

1. Frequencies: the printer roller (jobs/printer_roller_kelvin_voigt.yaml without the sheet, a uniform coarse mesh) rotating at
   19 rad/s with its Kelvin-Voigt damping: every eigenvalue of the reduced model (-modes -rom -rom_cutoff 5000, the
   modes clamped at the shaft below 5 kHz and the two static load responses; Coriolis, centrifugal softening and the
   damping reduced) below 0.8 of the cutoff matches the full model's -modes (same order and wave) within 0.1 % in
   frequency and in decay rate, and every full eigenvalue there has its reduced one.
2. Energy: the free roller spun up from rest (jobs/free.yaml, trapezoidal, to t = 5, -rom_cutoff 2: 189 modes): the
   reduced model's own discrete energy balance E^k - E^0 = sum of the load's work minus the Kelvin-Voigt and mass
   damping dissipations (the CSV's columns, docs/model.md section 2) holds to 1e-12 of the largest energy.
3. Transient: the same run against the full model's: R and alpha within 2 % and 0.5 % of their largest values, the
   energy within 0.5 %."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import SOURCE, Checker, read_csv, run  # noqa: E402

c = Checker("rom_free")
PRINTER = ["-options_file", os.path.join(SOURCE, "jobs", "printer_roller_kelvin_voigt.yaml"), "-obstacle", "false", "-mesh_h", "0.0012", "-mesh_h_contact", "0", "-quiet"]
CUT = 5000.0

run(PRINTER + ["-modes", "-modes_nev", "60", "-modes_csv", "rom_full_modes.csv"])
run(PRINTER + ["-modes", "-modes_nev", "60", "-rom", "-rom_cutoff", repr(CUT), "-modes_csv", "rom_modes.csv"])
full, red = read_csv("rom_full_modes.csv"), read_csv("rom_modes.csv")
w_top = 0.8 * 2 * math.pi * CUT
w_full_max = full["im"].max()


def match(src, dst, j):
    """The row of dst of the same order and wave nearest in frequency to row j of src"""
    same = [k for k in range(len(dst["im"])) if dst["order"][k] == src["order"][j] and dst["wave"][k] == src["wave"][j]]
    return min(same, key=lambda k: abs(dst["im"][k] - src["im"][j])) if same else None


worst_f = worst_g = 0.0
n_red = 0
for j in range(len(red["im"])):
    if red["im"][j] > min(w_top, w_full_max):
        continue
    n_red += 1
    k = match(red, full, j)
    if k is None:
        c.check(False, f"reduced eigenvalue {red['re'][j]:.4g} + {red['im'][j]:.6g} i (order {red['order'][j]:.0f} {red['wave'][j]}) has no full one")
        continue
    worst_f = max(worst_f, abs(red["im"][j] - full["im"][k]) / full["im"][k])
    worst_g = max(worst_g, abs(red["re"][j] - full["re"][k]) / abs(full["re"][k]))
c.check(n_red >= 10, f"{n_red} reduced eigenvalues below min(0.8 cutoff, the full run's highest) = {min(w_top, w_full_max):.0f} rad/s (>= 10)")
c.check(worst_f < 1e-3, f"reduced frequencies match the full model's within {worst_f:.2e} (< 1e-3)")
c.check(worst_g < 1e-3, f"reduced decay rates match the full model's within {worst_g:.2e} (< 1e-3)")
missing = [j for j in range(len(full["im"])) if full["im"][j] < min(w_top, red["im"].max()) and match(full, red, j) is None]
c.check(not missing, f"every full eigenvalue below the range of both has a reduced one ({len(missing)} missing)")

FREE = ["-options_file", os.path.join(SOURCE, "jobs", "free.yaml"), "-ts_scheme", "trapezoidal", "-ts_max_time", "5", "-quiet"]
run(FREE + ["-monitor_csv", "rom_full_free.csv"])
run(FREE + ["-rom", "-rom_cutoff", "2", "-monitor_csv", "rom_free.csv"])
a, b = read_csv("rom_full_free.csv"), read_csv("rom_free.csv")
works = np.cumsum(b["load_work"][1:] - b["damping_dissipation"][1:] - b["viscous_dissipation"][1:])
defect = np.max(np.abs(b["energy"][1:] - b["energy"][0] - works)) / np.max(np.abs(b["energy"]))
c.check(defect < 1e-12, f"the reduced model's energy balance holds to {defect:.1e} of its largest energy (< 1e-12)")
c.check(len(a["t"]) == len(b["t"]) and np.allclose(a["t"], b["t"]), "the reduced run has the full run's steps")
for col, tol in (("R", 0.02), ("alpha", 0.005), ("energy", 0.005)):
    err = np.max(np.abs(a[col] - b[col])) / np.max(np.abs(a[col]))
    c.check(err < tol, f"{col}: the reduced run within {err:.2e} of the full run's largest |{col}| (< {tol})")
c.close()

"""The issue's agreement of the reduced model with the full one (issue 37, docs/performance.md "Reduced-order
transient"): jobs/printer_roller_kelvin_voigt.yaml over 30 ms (press by the sheet for 3 ms, then feeding with velocity-weakening
Coulomb friction), the full model and -rom at its default cutoff (the modes clamped at the shaft up to where the
step's frequency error reaches -ts_phase_error, 9.9 kHz here, and the two static load responses), both CSVs read:
- the mean contact force and the mean friction force over the feeding (t > 3 ms) within 1 % and 2 % of the full
  model's;
- the friction force's largest spectral line over the feeding (Hann window, mean removed) within 1 % in frequency
  and 2 dB in level;
- the reduced run's own energy identity to round-off (as tests/rom_contact.py).
About 10 min of CPU (the full 30 ms, 75 s; the reduced model's modes)."""
import numpy as np

from rollertest import SOURCE, Checker, energy_defect, friction_line, read_csv, run

c = Checker("rom_printer")
SCENE = ["-options_file", f"{SOURCE}/jobs/printer_roller_kelvin_voigt.yaml", "-ts_max_time", "0.03", "-quiet"]
run(SCENE + ["-monitor_csv", "rom_printer_full.csv"])
run(SCENE + ["-rom", "-monitor_csv", "rom_printer_rom.csv"])
a, b = read_csv("rom_printer_full.csv"), read_csv("rom_printer_rom.csv")
c.check(len(a["t"]) == len(b["t"]) and np.allclose(a["t"], b["t"]), f"the reduced run has the full run's {len(a['t']) - 1} steps")
feed = a["t"] > 0.003
for col, tol in (("contact_force", 0.01), ("friction_force", 0.02)):
    fa, fb = a[col][feed].mean(), b[col][feed].mean()
    err = abs(fb - fa) / abs(fa)
    c.check(err < tol, f"mean {col} over the feeding: reduced {fb:.4g}, full {fa:.4g} N/m: within {100 * err:.2f} % (< {100 * tol:.0f} %)")

(f_a, l_a), (f_b, l_b) = friction_line(a), friction_line(b)
c.check(abs(f_b - f_a) / f_a < 0.01, f"the friction force's largest line: reduced {f_b:.1f} Hz, full {f_a:.1f} Hz (within 1 %)")
c.check(abs(l_b - l_a) < 2.0, f"its level: reduced {l_b:.1f} dB, full {l_a:.1f} dB (within 2 dB)")
defect = energy_defect(b)
c.check(defect < 1e-11, f"the reduced model's energy identity holds to {defect:.1e} of its largest energy (< 1e-11)")
c.close()

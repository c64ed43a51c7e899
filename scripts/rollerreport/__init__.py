"""rollerreport: the squeal report of Roller (docs/squeal.md section 9.1) as one importable package.

Run as `PYTHONPATH=scripts python3 -m rollerreport FOLDER`, or let `python3 -m rollerreport.run SCENE.yaml OUTDIR`
(docs/squeal.md section 9.2) run every step and then the report. It reuses the spectra of scripts/spectrum.py and the
whirl fits of scripts/squeal_fit.py (importable here as rollerreport.spectrum and rollerreport.squeal_fit; the
old scripts keep working unchanged) and adds
- sound: the WAV of what a listener near the sheet would hear (16-bit, 44.1 kHz) and its spectrogram;
- zones: the rolling roller with stick and slip zones coloured (GIF if Pillow is present, else a PNG strip);
- report: the verdict and the Markdown report;
- run: the driver (the CEA, the map, the seeded transient, scene.json, the report).
"""
import os
import sys

_SCRIPTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if _SCRIPTS not in sys.path:
    sys.path.insert(0, _SCRIPTS)

import spectrum  # noqa: E402,F401  (scripts/spectrum.py)
import squeal_fit  # noqa: E402,F401  (scripts/squeal_fit.py)

__all__ = ["spectrum", "squeal_fit", "sound", "zones", "report", "run"]

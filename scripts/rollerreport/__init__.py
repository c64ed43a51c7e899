"""rollerreport: the squeak report of Roller (docs/squeal.md section 9) as one importable package.

`PYTHONPATH=scripts python3 -m rollerreport.run SCENE.yaml OUTDIR` (section 9.2) runs every part the report needs
and writes it; `python3 -m rollerreport FOLDER` (section 9.1) writes the report of a folder that holds the parts.
Modules:
- run: the driver: the parts (CEA, map, transients, sound, animation, page), each runnable alone, journalled
  (journal) so that a re-run reuses what the folder holds, with their cost;
- mechanisms: flutter, stick-slip, forced resonance, each a function of the folder returning a dict;
- cycle: the limit cycle of a monitor series (stick in every period), the pitch of a periodic sound, the lock-in;
- onedof: a scene on -axle as rollerref's 1-DOF (the cross-check of the CEA's drive mode, the forced closed form);
- propensity: the odds over the real spread (Latin hypercube, Wilson's interval, the ranking), the 1-DOF's classes;
- propensity_fe: the propensity's cases on the finite elements (each case's CEA and its reduced start, -sweep_cases);
- ripple_sweep: the forced response against the ripple's frequency (a -sweep_cases map of reduced runs);
- disturbances: kicks of growing size about the steady state (a coexisting stick-slip cycle and the smallest kick to it);
- divergent: a clamped scene's start from rest and its map's divergent cells' (full transients, classified);
- run_lines: flutter read from the scene's own run where roller -modes refuses the scene (a line that grows);
- tables: a study's STEM.csv and STEM.json, written and read alike;
- radiation: the sound pressure at a listener from the roller's surface velocity (2-D cylinder, finite width);
- sound: the WAV of the simulated time at a stated level, the loudest line, A-weighting, the spectrogram;
- animation: the roller deforming, coloured by its velocity, with the stick and slip zones on the patch;
- page: report.html; report: the verdict, report.md and report.json; lines: the mesh's lines;
- spectrum, squeal_fit: the spectra and the whirl fits the tests and rollerplots use too.
"""
__all__ = ["spectrum", "squeal_fit", "lines", "sound", "radiation", "animation", "mechanisms", "cycle", "onedof",
           "propensity", "propensity_fe", "ripple_sweep", "disturbances", "divergent", "run_lines", "tables", "journal", "page", "report", "run"]

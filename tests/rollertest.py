"""Shared helpers for Roller's tests: run the executable, read its CSV, fit slopes, assert."""
import csv
import math
import os
import subprocess
import sys

import numpy as np

EXE = os.environ.get("ROLLER_EXE", "build/roller")
MPIEXEC = os.environ.get("ROLLER_MPIEXEC", "mpiexec")
SOURCE = os.environ.get("ROLLER_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# the packages of scripts/ (rollerref, rollerreport, rollerplots, rollertools): importable by the tests and by the
# `python3 -m PACKAGE.MODULE` commands they run
SCRIPTS = os.path.join(SOURCE, "scripts")
if SCRIPTS not in sys.path:
    sys.path.insert(0, SCRIPTS)
if SCRIPTS not in os.environ.get("PYTHONPATH", "").split(os.pathsep):
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (SCRIPTS, os.environ.get("PYTHONPATH")) if p)


def run(args, nproc=1, check=True):
    """Run roller with a list of options; return (returncode, stdout, stderr)."""
    cmd = [EXE] + [str(a) for a in args]
    if nproc > 1:  # more ranks than cores (a test of 3 ranks on a 2-core machine): Open MPI must be told
        over = ["--oversubscribe"] if nproc > (os.cpu_count() or 1) and os.path.basename(MPIEXEC) in ("mpiexec", "mpirun") else []
        cmd = [MPIEXEC] + over + ["-n", str(nproc)] + cmd
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if check and proc.returncode != 0:
        sys.stderr.write(proc.stdout + proc.stderr)
        raise SystemExit(f"FAIL: {' '.join(cmd)} exited {proc.returncode}")
    return proc.returncode, proc.stdout, proc.stderr


def read_csv(path):
    """A CSV (the monitor's, the modes') as a dict of numpy arrays keyed by column name (strings where not numbers)."""
    with open(path) as f:
        rows = list(csv.reader(f))
    head, body = rows[0], rows[1:]

    def column(i):
        try:
            return np.array([float(r[i]) for r in body])
        except ValueError:
            return np.array([r[i] for r in body])

    return {name: column(i) for i, name in enumerate(head)}


def energy_defect(d):
    """max_k |E^k - E^0 - (shaft + sheet work - friction work - summed dissipations)| / max |E| of a -monitor_csv."""
    diss = np.cumsum(d["contact_dissipation"] + d["damping_dissipation"] + d["viscous_dissipation"])
    bal = d["energy"] - d["energy"][0] - (d["shaft_work"] + d["sheet_work"] - d["friction_work"] - diss)
    return float(np.abs(bal).max() / np.abs(d["energy"]).max())


def friction_line(d, t0=0.003):
    """Frequency and level (dB of the unnormalized DFT: compare runs of the same step only) of the friction force's largest
    spectral line after t0 (Hann window, mean removed)."""
    feed = d["t"] > t0
    x = d["friction_force"][feed] - d["friction_force"][feed].mean()
    s = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    f = np.fft.rfftfreq(len(x), d["t"][1] - d["t"][0])
    k = 1 + int(np.argmax(s[1:]))
    return f[k], 20 * np.log10(s[k])


def rel_max_error(d, ref, q):
    """max over d's times of |d[q] - ref[q]| (ref interpolated in t), relative to max |ref[q]|."""
    return float(np.abs(d[q] - np.interp(d["t"], ref["t"], ref[q])).max() / np.abs(ref[q]).max())


def slope(hs, errs):
    """Least-squares slope of log(err) against log(h)."""
    return float(np.polyfit(np.log(hs), np.log(errs), 1)[0])


class Checker:
    """Collects named assertions, prints each, and exits non-zero if any failed."""

    def __init__(self, name):
        self.name, self.passed, self.failed = name, 0, 0

    def check(self, ok, what):
        print(("PASS " if ok else "FAIL ") + what, flush=True)
        if ok:
            self.passed += 1
        else:
            self.failed += 1

    def close(self):
        print(f"{self.name}: {self.passed} passed, {self.failed} failed")
        sys.exit(1 if self.failed or not self.passed else 0)


def scratch(prefix):
    """A temporary folder for a test's files, removed when the test's process exits (passed or failed: what failed is in
    its output)."""
    import atexit
    import shutil
    import tempfile

    d = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, d, True)
    return d


def maxwell_branches(h5path):
    """The generalized Maxwell rubber's branches (relaxation times tau_i, weights g_i) from a run's HDF5 parameters."""
    import h5py

    with h5py.File(h5path, "r") as f:
        par = dict(f["parameters"].attrs)
    nb = int(np.ravel(par["maxwell_branches"])[0])
    tau = np.array([float(np.ravel(par[f"maxwell_tau_{i}"])[0]) for i in range(nb)])
    g = np.array([float(np.ravel(par[f"maxwell_weight_{i}"])[0]) for i in range(nb)])
    return tau, g


def maxwell_modulus(s, tau, g):
    """G*(s)/mu = 1 + sum_i g_i s tau_i/(1 + s tau_i) (docs/model.md section 1.1)"""
    return 1 + np.sum(g * s * tau / (1 + s * tau))


def maxwell_oscillator_roots(w0, tau, g, tau_kv=0.0):
    """The roots of (s^2 + w0^2 (1 + s tau_kv)) prod(1 + s tau_j) + w0^2 sum_i g_i s tau_i prod_{j != i}(1 + s tau_j): an
    oscillator of relaxed frequency w0 on the Maxwell modulus (with a Kelvin-Voigt term tau_kv beside the branches).
    Returns the root with positive imaginary part and the real (creep) roots."""
    poly = np.poly1d([1.0, w0 * w0 * tau_kv, w0 * w0])
    for t in tau:
        poly *= np.poly1d([t, 1.0])
    for i, t in enumerate(tau):
        term = np.poly1d([w0 * w0 * g[i] * t, 0.0])
        for j, tj in enumerate(tau):
            if j != i:
                term *= np.poly1d([tj, 1.0])
        poly += term
    roots = poly.roots
    return next(r for r in roots if r.imag > 0), sorted(r.real for r in roots if abs(r.imag) < 1e-9 * abs(r))


def fit_maxwell_decay(t, a, creep):
    """Fit a(t) = e^{s t} (A cos w t + B sin w t) + sum_r C_r e^{r t} (the oscillator on the Maxwell modulus: its pair
    and its creep roots, maxwell_oscillator_roots) by least squares in (s, w), the amplitudes linear. Returns s, w and
    the largest residual over max |a|."""
    from scipy.optimize import least_squares

    def basis(p):
        return np.array([np.exp(p[0] * t) * np.cos(p[1] * t), np.exp(p[0] * t) * np.sin(p[1] * t)] + [np.exp(r * t) for r in creep]).T

    def residual(p):
        B = basis(p)
        return B @ np.linalg.lstsq(B, a, rcond=None)[0] - a

    zero = np.where(np.diff(np.sign(a)) != 0)[0]  # the first guess from the signal: its zero crossings
    fit = least_squares(residual, [-0.01, np.pi / np.diff(t[zero]).mean()], x_scale=[0.01, 0.1])
    return fit.x[0], fit.x[1], np.abs(fit.fun).max() / np.abs(a).max()


# report.html's probe: the page as written plus a script that puts what it loaded into the title (Chromium's
# --dump-dom after a virtual time budget), from a copy beside it (the same relative links)
PROBE = """<script>
function probe(){var a=document.querySelector('audio');
document.title='PROBE '+JSON.stringify({audio:a?a.duration:null,error:a&&a.error?a.error.code:null,
images:[...document.images].map(function(i){return [i.getAttribute('src'),i.naturalWidth,i.complete];})});}
window.addEventListener('load',function(){var a=document.querySelector('audio');
if(a&&a.readyState<1){a.addEventListener('loadedmetadata',probe);a.addEventListener('error',probe);}probe();});
</script>"""


def chromium_probe(browser, folder, page):
    """Open `page` (report.html's text) as folder/probe.html in headless Chromium: ({audio: duration, error, images:
    [[src, naturalWidth, complete]]} or None when the page did not run, the process)."""
    import json
    import re
    import shutil
    import subprocess
    import tempfile

    with open(os.path.join(folder, "probe.html"), "w") as f:
        f.write(page.replace("</body>", PROBE + "</body>"))
    profile = tempfile.mkdtemp(prefix="chromium_")
    cmd = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
           "--disable-sync", "--no-first-run", f"--user-data-dir={profile}", "--virtual-time-budget=10000", "--dump-dom",
           "file://" + os.path.join(folder, "probe.html")]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    shutil.rmtree(profile, ignore_errors=True)
    m = re.search(r"<title>PROBE (.*?)</title>", p.stdout)
    return (json.loads(m.group(1).replace("&quot;", '"')) if m else None), p

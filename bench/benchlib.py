"""Shared helpers of the benchmark scripts: run roller once and measure it.

run() starts the executable (ROLLER_EXE, default build/roller), optionally under mpiexec (ROLLER_MPIEXEC),
with -log_view written to a file, and returns the wall time, the CPU time (user + system of the process
tree, from wait4), the peak resident memory of the largest process (/usr/bin/time %M), the -log_view stages and
events, the CSV series (if -monitor_csv was asked for) and stdout.

The development machine has 2 cores and is shared with other jobs: wall time includes waiting for a core,
CPU time does not (but still includes slowdowns from shared caches and memory bandwidth). Compare runs by
ratios measured in one invocation of a bench script, and prefer the CPU time column when the load varies.
"""
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("ROLLER_EXE", os.path.join(ROOT, "build", "roller"))
MPIEXEC = os.environ.get("ROLLER_MPIEXEC", "mpiexec")
sys.path.insert(0, os.path.join(ROOT, "tests"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from logview import parse  # noqa: E402
from rollertest import read_csv  # noqa: E402

# Open MPI refuses to run as root without these (harmless otherwise)
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")


def command(args, nproc=1, launcher=False, exe=None):
    """The command line of `exe` (default EXE); under mpiexec when nproc > 1 or launcher (mpiexec -n 1: the same start-up
    as a parallel run)."""
    cmd = [exe or EXE] + [str(a) for a in args]
    if nproc > 1 or launcher:
        cmd = [MPIEXEC, "-n", str(nproc)] + cmd
    return cmd


def run(args, nproc=1, csv=False, logview=True, cwd=ROOT, launcher=False, exe=None):
    """Run roller (or another executable `exe`) with the options `args`; return a dict (see the module docstring)."""
    with tempfile.TemporaryDirectory() as tmp:
        extra = ["-quiet"]
        lv = os.path.join(tmp, "log.txt")
        if logview:
            extra += ["-log_view", ":" + lv]
        if csv:
            extra += ["-monitor_csv", os.path.join(tmp, "run.csv")]
        cmd = command(list(args) + extra, nproc, launcher, exe)
        out = open(os.path.join(tmp, "stdout"), "w+")
        # Peak memory through /usr/bin/time: the rusage of a child forked from this (large) Python process
        # counts the pages it shared with it before exec, so wait4's ru_maxrss would report Python's size.
        rss = os.path.join(tmp, "maxrss")
        timed = (["/usr/bin/time", "-f", "%M", "-o", rss] if os.access("/usr/bin/time", os.X_OK) else []) + cmd
        start = time.perf_counter()
        proc = subprocess.Popen(timed, stdout=out, stderr=subprocess.STDOUT, cwd=cwd)
        _, status, ru = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        text = out.read()
        out.close()
        if proc.returncode != 0:
            sys.stderr.write(text[-4000:])
            raise RuntimeError(f"{' '.join(cmd)} exited {proc.returncode}")
        maxrss = float("nan")
        if os.path.exists(rss):
            with open(rss) as f:
                maxrss = float(f.read().split()[-1]) / 1024.0
        res = {"cmd": " ".join(cmd), "wall": wall,
               "cpu": ru.ru_utime + ru.ru_stime, "maxrss_mb": maxrss, "stdout": text}
        if logview:
            with open(lv) as f:
                res["logview_text"] = f.read()
            res.update(parse(res["logview_text"]))
        if csv:
            res["series"] = read_csv(os.path.join(tmp, "run.csv"))
        return res


def shell(args, nproc=1, launcher=False):
    """The command line as a user would type it (relative to the repository, for the docs)."""
    exe = "build/roller"
    s = " ".join([exe] + [str(a) for a in args])
    return f"mpiexec -n {nproc} {s}" if nproc > 1 or launcher else s


def stage(res, name):
    return res.get("stages", {}).get(name, 0.0)


def event(res, stage_name, ev):
    """(count, time) of an event inside a stage, (0, 0.0) if absent."""
    return res.get("events", {}).get((stage_name, ev), (0, 0.0))


def save(name, text):
    """Print a result table and write it to bench/results/NAME."""
    print(text)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", name), "w") as f:
        f.write(text)

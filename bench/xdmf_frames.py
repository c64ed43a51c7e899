"""Cost of writing many field frames (-output F.h5 -output_every 1): total wall time, the "Roller output"
stage of -log_view, and the time per frame over the first and the last 100 frames, for one or more
binaries measured one after the other in this invocation (ratios within one invocation are what to
compare: see benchlib.py on the shared machine).

    /usr/bin/python3 bench/xdmf_frames.py --exe before=/tmp/xdmf-base/build/roller --exe after=build/roller
    # -> bench/results/xdmf_frames.md

Time per frame: -ts_monitor prints one line per step before that step's output, flushed; this script
stamps every line as it arrives, so the gap between the lines of steps k and k+1 is the output of frame k
plus the (constant, ~0.1 ms here) step k+1. With -output_every 1 every step is a frame. The final index
F.xmf of each binary is compared byte for byte with the first binary's.
"""
import argparse
import hashlib
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchlib import MPIEXEC, ROOT, shell  # noqa: E402
from logview import parse  # noqa: E402

MONITOR = re.compile(rb"^\s*(\d+) t ")
TICK = os.sysconf("SC_CLK_TCK")


def cpu_now(pid):
    """User + system CPU seconds of process pid so far (/proc, clock-tick resolution), nan if unreadable."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / TICK
    except (OSError, IndexError, ValueError):
        return float("nan")


def measure(exe, args, nproc, window):
    with tempfile.TemporaryDirectory() as tmp:
        lv = os.path.join(tmp, "log.txt")
        cmd = [exe] + [str(a) for a in args] + ["-ts_monitor", "-log_view", ":" + lv]
        if nproc > 1:
            cmd = [MPIEXEC, "-n", str(nproc)] + cmd
        stamps, cpus = {}, {}
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, cwd=tmp, bufsize=0)
        other = []
        for line in proc.stdout:
            now = time.perf_counter()
            m = MONITOR.match(line)
            if m:
                stamps[int(m.group(1))] = now
                cpus[int(m.group(1))] = cpu_now(proc.pid) if nproc == 1 else float("nan")
            else:
                other.append(line)
        _, status, ru = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        if proc.returncode != 0:
            sys.stderr.write(b"".join(other[-40:]).decode(errors="replace"))
            raise RuntimeError(f"{' '.join(cmd)} exited {proc.returncode}")
        with open(lv) as f:
            stages = parse(f.read())["stages"]
        with open(os.path.join(tmp, "f.xmf"), "rb") as f:
            xmf = f.read()
        left = [n for n in os.listdir(tmp) if "part" in n]
    n = max(stamps)
    gaps = [stamps[k + 1] - stamps[k] for k in range(n)]  # frame k (its output) + step k+1
    cpu_first = (cpus[window] - cpus[0]) / window
    cpu_last = (cpus[n] - cpus[n - window]) / window
    return {"wall": wall, "cpu": ru.ru_utime + ru.ru_stime, "output": stages.get("Roller output", float("nan")), "frames": n + 1,
            "cpu_first": cpu_first, "cpu_last": cpu_last, "first": sum(gaps[:window]) / window, "last": sum(gaps[-window:]) / window,
            "xmf_bytes": len(xmf), "xmf_md5": hashlib.md5(xmf).hexdigest(), "left": left, "n": n}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", action="append", default=[], help="label=path of a roller binary (repeatable)")
    ap.add_argument("--frames", type=int, default=2000, help="steps (= frames after the initial one)")
    ap.add_argument("--window", type=int, default=100, help="frames averaged at the start and at the end")
    ap.add_argument("--np", type=int, default=1, help="MPI ranks")
    ap.add_argument("--rounds", type=int, default=1, help="run the binaries in turn this many times, keep each one's fastest")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "xdmf_frames.md"))
    a = ap.parse_args()
    exes = [e.split("=", 1) for e in a.exe] or [["current", os.path.join(ROOT, "build", "roller")]]
    args = ["-mesh_h", "0.05", "-degree", "1", "-ts_dt", "0.0125", "-ts_max_time", "1e6", "-ts_max_steps", a.frames,
            "-output", "f.h5", "-output_every", 1, "-quiet"]
    runs = {label: [] for label, _ in exes}
    for rnd in range(a.rounds):
        for label, exe in exes:
            exe = os.path.abspath(exe)
            print(f"round {rnd + 1}, {label}: {exe}", flush=True)
            r = measure(exe, args, a.np, a.window)
            r["label"] = label
            print(f"  wall {r['wall']:.2f} s, CPU {r['cpu']:.2f} s, output stage {r['output']:.2f} s, first {1e3 * r['first']:.2f} ms/frame "
                  f"(CPU {1e3 * r['cpu_first']:.2f}), last {1e3 * r['last']:.2f} ms/frame (CPU {1e3 * r['cpu_last']:.2f}), {r['frames']} frames, index {r['xmf_bytes']} bytes, .part left {r['left']}",
                  flush=True)
            runs[label].append(r)
    # every quantity: its least value over the rounds (the machine is shared: a burst of another job's
    # I/O inflates one window of one run)
    rows = []
    for label, _ in exes:
        r = dict(runs[label][0])
        for q in ("wall", "cpu", "output", "first", "last", "cpu_first", "cpu_last"):
            r[q] = min(x[q] for x in runs[label])
        r["same"] = all(x["xmf_md5"] == runs[exes[0][0]][0]["xmf_md5"] for x in runs[label])
        rows.append(r)
    n = rows[0]["n"]
    w = a.window
    lines = [
        f"# Writing {rows[0]['frames']} field frames ({a.np} rank{'s' if a.np > 1 else ''})",
        "",
        "    /usr/bin/python3 bench/xdmf_frames.py " + " ".join(f"--exe {lab}={p}" for lab, p in exes)
        + (f" --frames {a.frames}" if a.frames != 2000 else "") + (f" --np {a.np}" if a.np > 1 else "")
        + (f" --window {a.window}" if a.window != 100 else "") + (f" --rounds {a.rounds}" if a.rounds > 1 else ""),
        "",
        "Each binary runs (plus `-ts_monitor -log_view` for the measurement):",
        "",
        "    " + shell(args, a.np),
        "",
        f"Time per frame = gap between consecutive `-ts_monitor` lines (the frame's output plus one step, "
        f"~0.1 ms), mean over frames 0-{w - 1} and {n - w}-{n - 1}; CPU per frame from /proc/PID/stat read at "
        f"the same lines (serial runs only; 10 ms ticks, so +-0.1 ms over 100 frames). CPU: user + system of the "
        f"process. The machine is shared: wall time includes waiting for the disk and for a core, CPU time does not. "
        + (f"Each number is the least of {a.rounds} rounds (the binaries in turn; every round below)." if a.rounds > 1 else "One run each, one after the other."),
        "",
        f"| binary | wall | CPU | stage `Roller output` | ms/frame, first {w} (CPU) | ms/frame, last {w} (CPU) | last / first (CPU) | final index | same index as `{rows[0]['label']}` |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(f"| {r['label']} | {r['wall']:.1f} s | {r['cpu']:.1f} s | {r['output']:.1f} s | {1e3 * r['first']:.1f} ({1e3 * r['cpu_first']:.1f}) | {1e3 * r['last']:.1f} ({1e3 * r['cpu_last']:.1f}) | "
                     f"{r['last'] / r['first']:.1f} ({r['cpu_last'] / r['cpu_first']:.1f}) | {r['xmf_bytes'] / 1e6:.2f} MB | {'yes' if r['same'] else 'NO'} |")
    if a.rounds > 1:
        lines += ["", "Every round:", "", "| round | binary | wall | CPU | output stage | ms/frame first (CPU) | ms/frame last (CPU) |", "|---|---|---|---|---|---|---|"]
        for rnd in range(a.rounds):
            for label, _ in exes:
                x = runs[label][rnd]
                lines.append(f"| {rnd + 1} | {label} | {x['wall']:.1f} s | {x['cpu']:.1f} s | {x['output']:.1f} s | {1e3 * x['first']:.1f} ({1e3 * x['cpu_first']:.1f}) | {1e3 * x['last']:.1f} ({1e3 * x['cpu_last']:.1f}) |")
    text = "\n".join(lines) + "\n"
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    with open(a.out, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

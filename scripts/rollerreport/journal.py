"""The report's journal (OUTDIR/journal.json): each part's inputs' hash, outputs, status and cost, so that a re-run
reuses what the folder already holds and the report states what each part cost.

A part is done when the journal holds it with status "ok", the same inputs' hash (its command or parameters, the
contents of the files it reads, and for a roller run the executable's) and every output present. Its cost: the CPU
time (user + system) of the child processes it ran (getrusage(RUSAGE_CHILDREN) around the run: mpiexec's ranks
included, as they are reaped by mpiexec) or of this process for a Python part, the wall time and the ranks it ran on
(rank-seconds = wall x ranks).
"""
import hashlib
import json
import os
import resource
import time

NAME = "journal.json"


def file_hash(path, cache={}):  # noqa: B006  (a per-process cache of (path, size, mtime) -> digest)
    """sha256 of a file's bytes ('' when missing)."""
    try:
        st = os.stat(path)
    except OSError:
        return ""
    key = (os.path.abspath(path), st.st_size, st.st_mtime_ns)
    if key not in cache:
        h = hashlib.sha256()
        with open(path, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        cache[key] = h.hexdigest()
    return cache[key]


def inputs_hash(params, files):
    """The hash of a part's inputs: its parameters (anything JSON can write: the command line, options) and the
    contents of the files it reads."""
    h = hashlib.sha256(json.dumps(params, sort_keys=True, default=str).encode())
    for path in sorted(files):
        h.update(os.path.basename(path).encode() + b"\0" + file_hash(path).encode())
    return h.hexdigest()


class Journal:
    def __init__(self, folder):
        self.folder = folder
        self.path = os.path.join(folder, NAME)
        try:
            with open(self.path) as f:
                self.parts = json.load(f)
        except (OSError, ValueError):
            self.parts = {}

    def save(self):
        tmp = self.path + ".part"
        with open(tmp, "w") as f:
            json.dump(self.parts, f, indent=1, default=str)
        os.replace(tmp, self.path)

    def done(self, name, digest):
        """True when part `name` finished with these inputs and its outputs are all present."""
        p = self.parts.get(name)
        return bool(p and p.get("status") == "ok" and p.get("inputs_hash") == digest
                    and all(os.path.exists(os.path.join(self.folder, o)) for o in p.get("outputs", [])))

    def run(self, name, digest, outputs, fn, ranks=1, what=""):
        """Run fn() (returns (ok, extra dict)) as part `name` unless it is done; record its cost. Returns the part's
        journal entry (with "reused": True when it was not run again)."""
        if self.done(name, digest):
            entry = dict(self.parts[name], reused=True)
            self.parts[name]["reused"] = True
            self.save()
            return entry
        for o in outputs:  # an earlier run's outputs are not this run's
            for stale in (o, o + ".part"):
                if os.path.exists(os.path.join(self.folder, stale)):
                    os.remove(os.path.join(self.folder, stale))
        children0, self0, wall0 = resource.getrusage(resource.RUSAGE_CHILDREN), resource.getrusage(resource.RUSAGE_SELF), time.time()
        ok, extra = fn()
        children1, self1, wall = resource.getrusage(resource.RUSAGE_CHILDREN), resource.getrusage(resource.RUSAGE_SELF), time.time() - wall0
        cpu_children = (children1.ru_utime - children0.ru_utime) + (children1.ru_stime - children0.ru_stime)
        cpu_self = (self1.ru_utime - self0.ru_utime) + (self1.ru_stime - self0.ru_stime)
        entry = {"what": what, "inputs_hash": digest, "outputs": [o for o in outputs if os.path.exists(os.path.join(self.folder, o))],
                 "status": "ok" if ok else "failed", "cpu_seconds": round(cpu_children + cpu_self, 2),
                 "cpu_children_seconds": round(cpu_children, 2), "cpu_python_seconds": round(cpu_self, 2),
                 "wall_seconds": round(wall, 2), "ranks": ranks, "rank_seconds": round(wall * ranks, 2),
                 "finished": time.strftime("%Y-%m-%dT%H:%M:%S"), "reused": False}
        entry.update(extra or {})
        self.parts[name] = entry
        self.save()
        return entry

    def cost_lines(self):
        """The report's cost table (Markdown) from the journal."""
        if not self.parts:
            return []
        md = ["| part | status | CPU (user+sys, s) | wall (s) | ranks | reused |", "|---|---|---|---|---|---|"]
        total_cpu = total_wall = 0.0
        for name, p in self.parts.items():
            md.append(f"| {name} | {p.get('status')} | {p.get('cpu_seconds', 0):.1f} | {p.get('wall_seconds', 0):.1f} | "
                      f"{p.get('ranks', 1)} | {'yes' if p.get('reused') else 'no'} |")
            total_cpu += p.get("cpu_seconds", 0) or 0
            total_wall += p.get("wall_seconds", 0) or 0
        md.append(f"| total | | {total_cpu:.1f} | {total_wall:.1f} | | |")
        return md

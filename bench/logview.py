"""Parse PETSc -log_view text: stage times and per-stage event counts/times."""
import re


def parse(text):
    """Return {'stages': {name: time}, 'events': {(stage, event): (count, time)}}."""
    stages, events = {}, {}
    for m in re.finditer(r"^\s*\d+:\s+(.+?):\s+([0-9.e+-]+)\s+[0-9.]+%", text, re.M):
        stages[m.group(1).strip()] = float(m.group(2))
    stage = None
    for line in text.splitlines():
        m = re.match(r"--- Event Stage \d+: (.+)", line)
        if m:
            stage = m.group(1).strip()
            continue
        m = re.match(r"^(\w+)\s+(\d+)\s+[0-9.]+\s+([0-9.e+-]+)\s", line)
        if m and stage is not None and (stage, m.group(1)) not in events:
            events[(stage, m.group(1))] = (int(m.group(2)), float(m.group(3)))
    return {"stages": stages, "events": events}

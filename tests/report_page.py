"""report.html opened in headless Chromium (Debian's chromium, scripts/install-deps.sh): the page of a synthetic report
folder (tests/rollerreport_data.py) loads its audio element with squeal.wav's duration and every image (the
spectrogram, the animation, the map) with its own width; every relative link and source of the page is a file of the
folder. The page is loaded as written, plus a script that puts what it loaded into the title (--dump-dom after a
virtual time budget), from a copy beside it (the same relative links)."""
import json
import os
import re
import shutil
import struct
import subprocess
import sys

import rollerreport_data as D
from rollertest import Checker, chromium_probe, scratch

def width(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] == b"\x89PNG\r\n\x1a\n":
        return struct.unpack(">I", head[16:20])[0]
    if head[:6] in (b"GIF87a", b"GIF89a"):
        return struct.unpack("<H", head[6:8])[0]
    return None


c = Checker("report_page")
browser = shutil.which("chromium") or shutil.which("chromium-browser")
c.check(browser is not None, f"chromium on the PATH ({browser}; scripts/install-deps.sh installs Debian's chromium)")
d = scratch("report_page_")
D.make(d, t_end=60.0)
r = subprocess.run([sys.executable, "-m", "rollerreport", d], capture_output=True, text=True)
c.check(r.returncode == 0 and os.path.exists(os.path.join(d, "report.html")), f"python3 -m rollerreport writes report.html ({r.stderr.strip()[-300:]})")
page = open(os.path.join(d, "report.html")).read()
refs = sorted(set(re.findall(r"(?:src|href)='([^']+)'", page)))
c.check(refs and all(not re.match(r"^[a-z]+:|^/", x) and os.path.exists(os.path.join(d, x)) for x in refs),
        f"every link and source of report.html is relative and a file of the folder: {refs}")
out = json.load(open(os.path.join(d, "report.json")))
if browser:
    got, p = chromium_probe(browser, d, page)
    c.check(got is not None, f"chromium ran the page (exit {p.returncode}{'' if got is not None else ': ' + p.stderr.strip()[-300:]})")
    got = got or {}
    dur = got.get("audio")
    c.check(dur is not None and got.get("error") is None and abs(dur - out["wav_seconds"]) < 1e-4,
            f"the audio element loads squeal.wav: duration {dur} s, the WAV's {out['wav_seconds']:.6f} s (error {got.get('error')})")
    imgs = got.get("images", [])
    names = [i[0] for i in imgs]
    c.check({"spectrogram.png", "map.png"} <= set(names) and any(n.endswith(".gif") for n in names)
            and all(w > 0 and w == width(os.path.join(d, src)) for src, w, _ in imgs),
            f"every image loads at its own width: {imgs}")
c.close()

#!/usr/bin/python3
"""P2/P3 spatial error of the order-0 modes (torsional w_t, second torsional, and breathing when found) of the
free annulus (-omega 0) against the exact annulus modes (scripts/rollerref/annulus_modes.py), per nu and h:
relative frequency error, unknowns, CPU (user+sys) of the `roller -modes` process. No transients: the mode
error is the spatial phase error per unit time (docs/model.md 6.2).
  bench/space_modes.py [--nus 0.3,0.4,0.45,0.49] [--hs 0.1,0.07,0.05,0.035] [--degrees 2,3] [--csv F]"""
import argparse, csv, io, os, re, subprocess, sys
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.environ["PYTHONPATH"] = os.path.join(root, "scripts") + os.pathsep + os.environ.get("PYTHONPATH", "")

def reference(nu):
    out = subprocess.run([sys.executable, "-m", "rollerref.annulus_modes", "--orders", "0", "--count", "3",
                          "--omega", "0", "--poisson", str(nu), "--n", "96"], capture_output=True, text=True, check=True).stdout
    return sorted(float(r["frequency"]) for r in csv.DictReader(io.StringIO(out)))

def run(args):
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    assert status == 0, out
    return out, ru.ru_utime + ru.ru_stime

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nus", default="0.3,0.4,0.45,0.49")
    ap.add_argument("--hs", default="0.1,0.07,0.05,0.035")
    ap.add_argument("--degrees", default="2,3")
    ap.add_argument("--nev", type=int, default=6)
    ap.add_argument("--extra", default="", help="more roller options, e.g. '-volumetric reduced'")
    ap.add_argument("--csv", default="-")
    a = ap.parse_args()
    f = sys.stdout if a.csv == "-" else open(a.csv, "w")
    w = csv.writer(f)
    w.writerow(["degree", "nu", "h", "unknowns", "cpu", "err_torsion", "err_torsion2", "err_breathing"])
    for nu in map(float, a.nus.split(",")):
        ref = reference(nu)
        for k in map(int, a.degrees.split(",")):
            for h in map(float, a.hs.split(",")):
                out, cpu = run([os.path.join(root, "build/roller"), "-modes", "-omega", "0", "-poisson", str(nu), "-degree", str(k), "-mesh_h", str(h),
                                "-modes_nev", str(a.nev), "-modes_csv", "/tmp/space_modes.csv"] + a.extra.split())
                n = int(re.search(r"(\d+) unknowns", out).group(1))
                fe = sorted(float(r["frequency"]) for r in csv.DictReader(open("/tmp/space_modes.csv")) if r["order"] == "0")
                errs = []
                for j in range(3):   # the discrete order-0 mode nearest each reference one
                    best = min(fe, key=lambda x: abs(x - ref[j])) if fe else float("nan")
                    errs.append((best - ref[j]) / ref[j] if fe and abs(best - ref[j]) < 0.02 * ref[j] else float("nan"))
                w.writerow([k, nu, h, n, f"{cpu:.2f}"] + [f"{e:.2e}" for e in errs])
                f.flush()

if __name__ == "__main__":
    main()

"""-sweep (src/sweep/sweep.c, docs/squeal.md section 6): a 3 x 2 map (omega 0, 0.1, 0.2 times young 0.1, 0.2) of the free
annulus on the coarse mesh -mesh_h 0.08, by one `mpiexec -n 2` (two sub-communicators of one rank, the cases
round-robin) and by one rank. Asserted:
  - the gathered CSV has every case, in order, with its values of the swept options (the last varies fastest);
  - each case's eigenvalues (re, im, order, wave) are those of a separate `roller -modes -modes_csv` run with the
    same options, to 1e-8 of the largest |lambda| (each case is that run, on its own sub-communicator);
  - 1 and 2 ranks give the same CSV (to 1e-8; each case runs on one rank either way, so in fact bit for bit);
  - the Campbell diagram's physics: at omega = 0 the two modes of each order n = 1..3 are standing waves of equal
    frequency (within 1e-3, the mesh's asymmetry), at omega > 0 they split into a forward and a backward wave,
    and the splitting grows with omega (Bryan: about 2 gamma_n omega);
  - -sweep_slice: the two slices 0,2 and 1,2, merged by scripts/rollertools/merge_sweep.py, are the whole map;
  - scripts/rollerplots/sweep.py draws the Campbell diagram."""
import csv
import os
import subprocess
import sys

import numpy as np

from rollertest import SOURCE, Checker, run

OMEGA, YOUNG = [0.0, 0.1, 0.2], [0.1, 0.2]
BASE = ["-modes", "-mesh_h", 0.08, "-quiet"]
SWEEP = BASE + ["-sweep_omega", "0,0.1,0.2", "-sweep_young", "0.1,0.2"]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def by_case(table):
    cases = {}
    for r in table:
        cases.setdefault(int(r["case"]), []).append(r)
    return cases


def same(a, b, tol):
    """Same eigenvalues in the same order with the same order and wave; |lambda| differences relative to max |lambda|."""
    if len(a) != len(b):
        return False, float("inf")
    la = np.array([complex(float(r["re"]), float(r["im"])) for r in a])
    lb = np.array([complex(float(r["re"]), float(r["im"])) for r in b])
    err = float(np.abs(la - lb).max() / np.abs(la).max())
    labels = all(r["order"] == s["order"] and r["wave"] == s["wave"] for r, s in zip(a, b))
    return labels and err < tol, err


c = Checker("modes_sweep")
run(SWEEP + ["-sweep", "sweep_np2.csv"], nproc=2)
run(SWEEP + ["-sweep", "sweep_np1.csv"])
np2, np1 = rows("sweep_np2.csv"), rows("sweep_np1.csv")
cases = by_case(np2)
expect = [(w, e) for w in OMEGA for e in YOUNG]
c.check(sorted(cases) == list(range(len(expect))) and [int(r["case"]) for r in np2] == sorted(int(r["case"]) for r in np2), f"every case 0..{len(expect) - 1} present, sorted: {sorted(cases)}")
c.check(all(float(cases[k][0]["omega"]) == w and float(cases[k][0]["young"]) == e for k, (w, e) in enumerate(expect)), "each case's omega, young are the product's (young fastest)")
c.check(list(np2[0].keys()) == ["case", "omega", "young", "re", "im", "frequency", "growth_rate", "order", "wave", "error"], f"columns {','.join(np2[0].keys())}")

for k, (w, e) in enumerate(expect):
    run(BASE + ["-omega", w, "-young", e, "-modes_csv", f"single_{k}.csv"])
    ok, err = same(cases[k], rows(f"single_{k}.csv"), 1e-8)
    c.check(ok, f"case {k} (omega {w}, young {e}): {len(cases[k])} eigenvalues = the single run's, max difference {err:.1e} of max |lambda| (< 1e-8)")

ok, err = same(np1, np2, 1e-8)
identical = open("sweep_np1.csv").read() == open("sweep_np2.csv").read()
c.check(ok, f"1 rank and 2 ranks: the same {len(np1)} rows, max difference {err:.1e} of max |lambda| (< 1e-8); identical bytes: {identical}")

# Campbell: the order-n pair of each case
for k, (w, e) in enumerate(expect):
    for n in (1, 2, 3):
        pair = sorted((float(r["frequency"]), r["wave"]) for r in cases[k] if int(r["order"]) == n)
        if len(pair) != 2:
            c.check(False, f"case {k}: order {n} has {len(pair)} modes, expected 2")
            continue
        split = (pair[1][0] - pair[0][0]) / pair[0][0]
        if w == 0:
            c.check(split < 1e-3 and pair[0][1] == pair[1][1] == "standing", f"omega 0, young {e}, n = {n}: two standing waves, frequencies {pair[0][0]:.6f}, {pair[1][0]:.6f} equal to {split:.1e} (< 1e-3)")
        else:
            prev = [r for r in cases[expect.index((OMEGA[OMEGA.index(w) - 1], e))] if int(r["order"]) == n]
            f_prev = sorted(float(r["frequency"]) for r in prev)
            split_prev = (f_prev[1] - f_prev[0]) / f_prev[0]
            c.check({pair[0][1], pair[1][1]} == {"forward", "backward"} and split > 1.5 * split_prev and split > 0.02,
                    f"omega {w}, young {e}, n = {n}: forward and backward, splitting {split:.4f} > 1.5 x {split_prev:.4f} (omega {OMEGA[OMEGA.index(w) - 1]})")

# the job array's way: two slices, merged
run(SWEEP + ["-sweep", "part_0.csv", "-sweep_slice", "0,2"])
run(SWEEP + ["-sweep", "part_1.csv", "-sweep_slice", "1,2"], nproc=2)
part0 = by_case(rows("part_0.csv"))
c.check(sorted(part0) == [0, 2, 4], f"-sweep_slice 0,2 takes the even cases: {sorted(part0)}")
merge = subprocess.run([sys.executable, "-m", "rollertools.merge_sweep", "part_0.csv", "part_1.csv", "-o", "merged.csv", "--cases", "6"], capture_output=True, text=True)
c.check(merge.returncode == 0 and open("merged.csv").read() == open("sweep_np1.csv").read(), f"slices 0,2 and 1,2 merged = the whole map ({merge.stdout.strip() or merge.stderr.strip()[-200:]})")

# the picture
plot = subprocess.run([sys.executable, "-m", "rollerplots.sweep", "sweep_np2.csv", "--x", "omega", "--where", "young=0.1", "--out", "campbell.png"], capture_output=True, text=True)
c.check(plot.returncode == 0 and os.path.getsize("campbell.png") > 10000, f"rollerplots.sweep draws campbell.png ({(plot.stdout + plot.stderr).strip()[-200:]})")
c.close()

"""Output (src/io/output.c, docs/output.md): the XDMF index is valid XML whose every HDF5 reference exists
with the stated shape and type, its times are the CSV's; the fields are right: displacement_lab is
R(theta)(x + xi) - x recomputed from /geometry/vertices, displacement and the CSV theta, the boundary
integrals of the written displacement give the CSV's R and alpha, |sigma| is the mean over the cells
around each vertex of |sigma| recomputed from the P1 displacement; a killed run leaves only .part files,
indexed up to its last written step (exactly the steps in the HDF5 file, but for one being written), the
index grown in place while the run went (each version a prefix of the next, without its closing tags); a
complete run leaves no .part file.

    output_xdmf.py        serial (P1 and P2, killed run)
    output_xdmf.py mpi    the same checks on 2 ranks (P1)

Discretization: the output format does not depend on it; the degree is given where a check depends on it (P1
for the recomputed R, alpha and |sigma|), the killed run uses the default (P2 curved). -ts_dt 0.0125 is given
so that the 20 steps of a run span t = 0.25 and the fields are well away from rest (the default dt from
-ts_phase_error, 0.00172, would end them at t = 0.034).
"""
import os
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import h5py
import numpy as np

from rollertest import EXE, MPIEXEC, Checker, read_csv, run

MESH = ["-mesh_h", "0.05", "-ts_dt", "0.0125"]
chk = Checker("output_xdmf")


def numbers(text):
    return [int(v) for v in text.split()]


def resolve(root, item):
    """Follow a Reference="XML" DataItem (an XPath into this document) to the item it names."""
    if item.get("Reference") != "XML":
        return item
    path = item.text.strip()
    assert path.startswith("/Xdmf/"), path
    found = root.find("./" + path[len("/Xdmf/"):])
    assert found is not None, f"dangling reference {path}"
    return found


def check_hdf_item(item, base, exact):
    """An HDF DataItem: the file exists, the dataset exists, its shape and type are those stated.
    With exact=False (a killed run) the steps dimension of a field may have grown past the stated one: the
    run was killed while writing a step it had not indexed yet."""
    fname, dset = item.text.strip().rsplit(":", 1)
    stated = tuple(numbers(item.get("Dimensions")))
    with h5py.File(os.path.join(base, fname), "r") as f:
        assert dset in f, f"{fname} has no dataset {dset}"
        d = f[dset]
        shape = d.shape
        if exact or not dset.startswith("/vertex_fields"):
            assert shape == stated, f"{dset}: file {shape}, XDMF {stated}"
        else:
            assert shape[1:] == stated[1:] and shape[0] >= stated[0], f"{dset}: file {shape}, XDMF {stated}"
        kind = "Int" if d.dtype.kind in "iu" else "Float"
        assert item.get("NumberType", "Float") == kind, f"{dset}: {d.dtype} stated {item.get('NumberType')}"
        assert int(item.get("Precision", "4")) == d.dtype.itemsize, f"{dset}: {d.dtype} stated precision {item.get('Precision')}"
    return fname, dset, stated


def check_xdmf(xmf, exact=True):
    """Parse the index and check every reference; return (h5 file name, times, {attribute: dataset})."""
    base = os.path.dirname(os.path.abspath(xmf))
    root = ET.parse(xmf).getroot()
    assert root.tag == "Xdmf", root.tag
    domain = root.find("Domain")
    series = domain.find("Grid")
    assert series.get("GridType") == "Collection" and series.get("CollectionType") == "Temporal", "no temporal collection"
    h5names, times, attrs = set(), [], {}
    for k, grid in enumerate(series.findall("Grid")):
        times.append(float(grid.find("Time").get("Value")))
        topo = grid.find("Topology")
        cells = resolve(root, topo.find("DataItem"))
        h5, _, cdims = check_hdf_item(cells, base, True)
        h5names.add(h5)
        assert topo.get("TopologyType") == "Triangle" and cdims[1] == 3, f"{topo.get('TopologyType')} with {cdims}"
        assert int(topo.get("NumberOfElements")) == cdims[0], f"NumberOfElements {topo.get('NumberOfElements')} for {cdims}"
        geom = grid.find("Geometry")
        assert geom.get("GeometryType") == "XY", geom.get("GeometryType")
        h5, _, vdims = check_hdf_item(resolve(root, geom.find("DataItem")), base, True)
        h5names.add(h5)
        assert vdims[1] == 2, vdims
        nv = vdims[0]
        with h5py.File(os.path.join(base, h5), "r") as f:
            cmax = f["/viz/topology/cells"][:].max()
        assert cmax < nv, f"cells refer to vertex {cmax} of {nv}"
        for attr in grid.findall("Attribute"):
            assert attr.get("Center") == "Node", attr.get("Center")
            slab = attr.find("DataItem")
            assert slab.get("ItemType") == "HyperSlab", slab.get("ItemType")
            sel, data = slab.findall("DataItem")
            h5, dset, ddims = check_hdf_item(data, base, exact)
            h5names.add(h5)
            rows = np.array(numbers(sel.text)).reshape(numbers(sel.get("Dimensions")))
            start, stride, count = rows
            assert len(start) == len(ddims) and all(stride == 1), f"{dset}: slab {rows.tolist()} of {ddims}"
            assert start[0] == k and count[0] == 1 and all(start[1:] == 0), f"{dset} step {k}: slab {rows.tolist()}"
            assert all(start + count <= ddims), f"{dset}: slab {rows.tolist()} outside {ddims}"
            assert tuple(count) == tuple(numbers(slab.get("Dimensions"))), f"{dset}: HyperSlab Dimensions {slab.get('Dimensions')} for count {count}"
            assert count[1] == nv, f"{dset}: {count[1]} values for {nv} vertices"
            vector = attr.get("AttributeType") == "Vector"
            assert (vector and len(count) == 3 and count[2] == 3) or (not vector and len(count) == 2), f"{dset}: {attr.get('AttributeType')} of {count}"
            attrs.setdefault(attr.get("Name"), dset)
    assert len(h5names) == 1, h5names
    return h5names.pop(), np.array(times), attrs


def boundary_edges(x, cells, r_mid):
    """Edges of one cell only, both ends outside r_mid: the polygonal Gamma_C."""
    edges = np.sort(np.concatenate([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]]), axis=1)
    uniq, cnt = np.unique(edges, axis=0, return_counts=True)
    e = uniq[cnt == 1]
    r = np.linalg.norm(x, axis=1)
    return e[(r[e[:, 0]] > r_mid) & (r[e[:, 1]] > r_mid)]


def boundary_means(x, xi, edges):
    """R and alpha of docs/model.md section 4 for the P1 field xi: 5-point Gauss on every straight outer edge,
    as diagnostics.c does."""
    s, w = np.polynomial.legendre.leggauss(5)
    s, w = 0.5 * (s + 1), 0.5 * w
    a, b = x[edges[:, 0]], x[edges[:, 1]]
    length = np.linalg.norm(b - a, axis=1)
    R = alpha = 0.0
    for si, wi in zip(s, w):
        p = (1 - si) * a + si * b
        u = (1 - si) * xi[edges[:, 0]] + si * xi[edges[:, 1]]
        r = np.linalg.norm(p, axis=1)
        R += np.sum(wi * length * (u[:, 0] * p[:, 0] + u[:, 1] * p[:, 1]) / r)
        alpha += np.sum(wi * length * (-u[:, 0] * p[:, 1] + u[:, 1] * p[:, 0]) / r)
    return R / length.sum(), alpha / length.sum()


def stress_p1(x, cells, xi, young, poisson):
    """|sigma| of the P1 field xi on every cell, then the mean over the cells around each vertex."""
    lam = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
    mu = young / (2 * (1 + poisson))
    p = x[cells]
    J = np.stack([p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]], axis=2)  # columns: edge vectors
    U = np.stack([xi[cells[:, 1]] - xi[cells[:, 0]], xi[cells[:, 2]] - xi[cells[:, 0]]], axis=2)
    G = U @ np.linalg.inv(J)  # G[c, i, j] = d u_i / d x_j
    eps = 0.5 * (G + G.transpose(0, 2, 1))
    tr = eps[:, 0, 0] + eps[:, 1, 1]
    sig = 2 * mu * eps + lam * tr[:, None, None] * np.eye(2)
    cell_norm = np.sqrt((sig ** 2).sum(axis=(1, 2)))
    total = np.zeros(len(x))
    count = np.zeros(len(x))
    for k in range(3):
        np.add.at(total, cells[:, k], cell_norm)
        np.add.at(count, cells[:, k], 1)
    return total / count


def check_run(tag, degree, nproc, steps=20, every=5, scheme=None):
    h5, xmf, csvf = f"{tag}.h5", f"{tag}.xmf", f"{tag}.csv"
    run(MESH + ["-degree", degree, "-ts_max_steps", steps, "-output", h5, "-output_every", every,
                "-monitor_csv", csvf, "-quiet"] + (["-ts_scheme", scheme] if scheme else []), nproc=nproc)
    left = [n for n in os.listdir(".") if n.startswith(tag + ".") and "part" in n]
    chk.check(os.path.exists(h5) and os.path.exists(xmf) and os.path.exists(csvf) and not left,
              f"{tag}: {h5}, {xmf}, {csvf} present, no .part file left ({left})")
    try:
        name, times, attrs = check_xdmf(xmf)
        ok, why = True, ""
    except (AssertionError, KeyError, OSError, ET.ParseError) as e:
        ok, why = False, str(e)
    chk.check(ok, f"{tag}: {xmf} parses, every HDF5 reference exists with the stated shape and type {why}")
    if not ok:
        return
    chk.check(name == h5 and {"displacement", "displacement_lab", "stress_norm", "velocity"} <= set(attrs),
              f"{tag}: the index refers to {name} with attributes {sorted(attrs)}")
    csv = read_csv(csvf)
    out_steps = np.arange(0, steps + 1, every)
    with h5py.File(h5, "r") as f:
        x = f["/geometry/vertices"][:]
        cells = f["/viz/topology/cells"][:]
        t5 = f["/time"][:].ravel()
        xi = f[attrs["displacement"]][:]
        lab = f[attrs["displacement_lab"]][:]
        vel = f[attrs["velocity"]][:]
        sn = f[attrs["stress_norm"]][:]
        par = dict(f["/parameters"].attrs)
        diag = {k: f["/diagnostics/" + k][:] for k in ("step", "t", "R", "alpha", "energy")}
    chk.check(all(np.array_equal(diag[k], csv[k]) for k in diag),
              f"{tag}: /diagnostics holds the CSV's step, t, R, alpha, energy for all {len(diag['t'])} steps, bit for bit")
    chk.check(len(times) == len(out_steps) and np.allclose(times, csv["t"][out_steps], rtol=0, atol=1e-14)
              and np.allclose(t5, times, rtol=0, atol=0),
              f"{tag}: XDMF times = /time = CSV t at steps {out_steps.tolist()}")
    chk.check(np.all(xi[:, :, 2] == 0) and np.all(lab[:, :, 2] == 0) and np.all(vel[:, :, 2] == 0),
              f"{tag}: vectors are 3-component with zero z")
    err = 0.0
    for k, s in enumerate(out_steps):
        th = csv["theta"][s]
        c, sn_ = np.cos(th), np.sin(th)
        p = x + xi[k, :, :2]
        expect = np.stack([c * p[:, 0] - sn_ * p[:, 1], sn_ * p[:, 0] + c * p[:, 1]], axis=1) - x
        err = max(err, np.abs(lab[k, :, :2] - expect).max())
    scale = np.abs(lab).max()
    chk.check(err <= 1e-13 * max(scale, 1.0) and scale > 1e-3,
              f"{tag}: displacement_lab = R(theta)(x + xi) - x, max error {err:.2e} (|lab| up to {scale:.3g})")
    chk.check(np.all(np.isfinite(sn)) and sn.min() >= 0 and sn[-1].max() > 0,
              f"{tag}: stress_norm finite, >= 0, not all zero (max {sn.max():.3e})")
    chk.check(np.abs(vel[0]).max() == 0 and np.abs(xi[0]).max() == 0, f"{tag}: at rest at t = 0")
    if every == 1 and scheme in ("dmf", "trapezoidal"):
        ev = np.abs(vel[1:] - (xi[1:] - xi[:-1]) / par["dt"]).max()
        chk.check(ev <= 1e-12 * np.abs(vel).max(), f"{tag}: velocity = (xi^k - xi^(k-1))/dt, max error {ev:.1e}")
    elif every == 1:  # the one-step scheme's own velocity v^k: the centred difference of xi to O(dt^2)
        ev = np.abs(vel[1:-1] - (xi[2:] - xi[:-2]) / (2 * par["dt"])).max()
        chk.check(ev <= 1e-2 * np.abs(vel).max(), f"{tag}: velocity v^k = (xi^(k+1) - xi^(k-1))/(2 dt) + O(dt^2), "
                  f"max difference {ev / np.abs(vel).max():.1e} of |v|")
    if degree == 1:
        edges = boundary_edges(x, cells, 0.5 * (par["r_inner"] + par["r_outer"]))
        eR = eA = 0.0
        for k, s in enumerate(out_steps):
            R, A = boundary_means(x, xi[k, :, :2], edges)
            eR = max(eR, abs(R - csv["R"][s]))
            eA = max(eA, abs(A - csv["alpha"][s]))
        Rs = np.abs(csv["R"]).max()
        chk.check(eR <= 1e-9 * Rs and eA <= 1e-9 * max(np.abs(csv["alpha"]).max(), Rs),
                  f"{tag}: R, alpha integrated from the written displacement = CSV (errors {eR:.1e}, {eA:.1e}; |R| up to {Rs:.2e})")
        es = 0.0
        for k in range(len(out_steps)):
            es = max(es, np.abs(sn[k] - stress_p1(x, cells, xi[k, :, :2], par["young"], par["poisson"])).max())
        chk.check(es <= 1e-12 * max(sn.max(), 1e-30), f"{tag}: stress_norm = cell mean of |sigma| recomputed from P1 xi, max error {es:.1e}")


def check_killed(tag):
    """SIGKILL a long run once its index has 3 steps: only .part files remain and they are consistent;
    stale complete-looking files of an earlier run with the same names are gone."""
    h5, xmf, csvf = f"{tag}.h5", f"{tag}.xmf", f"{tag}.csv"
    for n in (h5, xmf, csvf):
        with open(n, "w") as f:
            f.write("stale\n")
    part = f"{tag}.part.xmf"
    if os.path.exists(part):
        os.remove(part)
    proc = subprocess.Popen([EXE] + MESH + ["-ts_max_time", "1e6", "-output", h5, "-output_every", "4",
                                            "-monitor_csv", csvf, "-quiet"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 120
    steps = 0
    seen = []  # (steps, text) of every complete index read while the run goes
    while time.time() < deadline and proc.poll() is None:
        try:
            with open(part) as f:
                text = f.read()
            steps = len(ET.fromstring(text).findall("./Domain/Grid/Grid"))
            seen.append((steps, text))
        except (OSError, ET.ParseError):
            steps = 0  # not created yet, or caught in the middle of a write
        if steps >= 3:
            break
        time.sleep(0.05)
    running = proc.poll() is None
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    chk.check(running and steps >= 3, f"{tag}: killed while running, with {steps} steps indexed")
    gone = [n for n in (h5, xmf, csvf) if os.path.exists(n)]
    chk.check(not gone and os.path.exists(h5 + ".part") and os.path.exists(csvf + ".part"),
              f"{tag}: no complete-looking file left ({gone}); {h5}.part, {csvf}.part, {part} are")
    try:
        name, times, _ = check_xdmf(part, exact=False)
        ok, why = name == h5 + ".part" and len(times) >= 3, f"(refers to {name}, {len(times)} steps)"
    except (AssertionError, KeyError, OSError, ET.ParseError) as e:
        ok, why = False, str(e)
    chk.check(ok, f"{tag}: the index of the killed run is valid {why}")
    if ok:
        with h5py.File(h5 + ".part", "r") as f:
            t5 = f["/time"][:].ravel()
        names = [g.get("Name") for g in ET.parse(part).getroot().findall("./Domain/Grid/Grid")]
        chk.check(names == [f"step {k}" for k in range(len(times))] and len(times) <= len(t5) <= len(times) + 1
                  and np.array_equal(times, t5[:len(times)]),
                  f"{tag}: the killed run's index names exactly the steps written, in order: {len(times)} indexed, "
                  f"{len(t5)} in {h5}.part (at most one written and not yet indexed)")
    # appended in place, never rewritten: every index seen, without its closing tags, starts the next one
    with open(part) as f:
        final = f.read()
    seen.append((len(times) if ok else -1, final))
    tail = "    </Grid>\n  </Domain>\n</Xdmf>\n"
    grows = all(a.endswith(tail) and b.startswith(a[:-len(tail)]) and nb >= na
                for (na, a), (nb, b) in zip(seen, seen[1:]))
    chk.check(len(seen) >= 2 and grows, f"{tag}: the index grew in place over {len(seen)} readings ({[n for n, _ in seen]} steps)")
    with open(csvf + ".part") as f:
        rows = f.read().splitlines()
    chk.check(len(rows) > 4 * (len(times) - 1) if ok else False, f"{tag}: the CSV of the killed run has {len(rows) - 1} rows")


if len(sys.argv) > 1 and sys.argv[1] == "mpi":
    check_run("mpi_p1", 1, 2)
else:
    check_run("p1", 1, 1)
    check_run("p2", 2, 1, every=1)
    check_run("p2_trapezoidal", 2, 1, every=1, scheme="trapezoidal")
    check_killed("killed")
chk.close()

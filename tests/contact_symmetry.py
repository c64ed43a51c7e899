"""omega = 0 compression is mirror-symmetric (issue 4).
1. On a mesh that is exactly symmetric about the y axis (the right half meshed by gmsh, mirrored here), the
   computed motion must be symmetric to solver round-off: the mean tangential displacement alpha stays below
   1e-8 max|R|, and the contact set is symmetric along t^k: s_min = -s_max and the force centroid is 0, to
   1e-10 (from -contact_monitor, written as a CSV).
2. On the ordinary (unsymmetric) gmsh meshes the asymmetry is discretization error: max|alpha|/max|R|
   shrinks by at least a factor 1.5 when h is halved (measured with dt = 0.0125: 0.54 at h = 0.05,
   0.21 at h = 0.025).

Discretization: 1. holds for any discretization: P1 and P2 are given, dt is Roller's default (from
-ts_phase_error: 0.0077 for t <= 1; the Coriolis velocity plays no part at omega = 0). 2. measures a P1
discretization error, so it pins what it was measured with: -degree 1, -ts_dt 0.0125 (the default is P2)."""
from contact_meshes import symmetric_mesh
from rollertest import Checker, read_csv, run

SCENE = ["-obstacle", "-obstacle_speed", 0.05, "-obstacle_depth", 0.01, "-omega", 0, "-damping", 1, "-quiet"]


def monitor(path):
    """The -contact_monitor CSV as (nodes, force, s_min, s_max, s_centroid) per step."""
    m = read_csv(path)
    return list(zip(m["nodes"].astype(int), m["force"], m["s_min"], m["s_max"], m["s_centroid"]))


c = Checker("contact_symmetry")

# 1. exactly symmetric mesh, P1 and P2
symmetric_mesh("symmetric.msh", 0.05)
for degree in (1, 2):
    csv = f"sym_p{degree}.csv"
    contact = f"sym_p{degree}_contact.csv"
    run(["-dm_plex_filename", "symmetric.msh", "-degree", degree, "-ts_max_time", 1, "-monitor_csv", csv,
         "-contact_monitor", f"ascii:{contact}:ascii_csv"] + SCENE)
    d, mon = read_csv(csv), monitor(contact)
    ratio = max(abs(d["alpha"])) / max(abs(d["R"]))
    touching = [m for m in mon if m[0] > 0]
    asym = max(abs(m[2] + m[3]) for m in touching)
    cent = max(abs(m[4]) for m in touching)
    c.check(len(touching) > 10, f"P{degree} symmetric mesh: contact in {len(touching)} steps (up to {max(m[0] for m in mon)} nodes)")
    c.check(ratio < 1e-8, f"P{degree} symmetric mesh: max|alpha|/max|R| = {ratio:.2e} < 1e-8")
    c.check(asym < 1e-10 and cent < 1e-10, f"P{degree} symmetric mesh: contact set |s_min + s_max| <= {asym:.2e}, |centroid| <= {cent:.2e} (< 1e-10)")

# 2. ordinary meshes: asymmetry is discretization error
ratios = []
for h in (0.05, 0.025):
    csv = f"gmsh_{h}.csv"
    run(["-mesh_h", h, "-degree", 1, "-ts_dt", 0.0125, "-ts_max_time", 1, "-monitor_csv", csv] + SCENE)
    d = read_csv(csv)
    ratios.append(max(abs(d["alpha"])) / max(abs(d["R"])))
    print(f"h = {h}: max|alpha|/max|R| = {ratios[-1]:.3e}")
c.check(ratios[0] / ratios[1] > 1.5, f"max|alpha|/max|R| shrinks with h: {ratios[0]:.3e} -> {ratios[1]:.3e} (factor {ratios[0] / ratios[1]:.2f} > 1.5)")
c.close()

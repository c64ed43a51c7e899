"""Meshes for the contact tests (a helper module, not a test): the annulus r_inner < |x| < r_outer exactly
mirror-symmetric about the y axis, so that omega = 0 compression by the obstacle below is symmetric to
round-off. gmsh meshes the right half (msh 2.2), the mirror image is added here, and the whole is written
as msh 2.2 with the physical groups Roller expects (inner, outer, body).

Optionally graded: edge length h_contact within distance `zone` of the bottom point (0, -r_outer), where
the obstacle touches, growing linearly to h at distance `zone + grow` (gmsh Distance + Threshold fields).
This resolves a small contact width (the Hertz check, tests/contact_static.py) at a small cost."""
import subprocess

HALF_GEO = """
r_inner = {r_inner}; r_outer = {r_outer}; h = {h};
Point(1) = {{0, 0, 0, h}};
Point(2) = {{0, -r_inner, 0, h}}; Point(3) = {{r_inner, 0, 0, h}}; Point(4) = {{0, r_inner, 0, h}};
Point(5) = {{0, -r_outer, 0, h}}; Point(6) = {{r_outer, 0, 0, h}}; Point(7) = {{0, r_outer, 0, h}};
Circle(1) = {{2, 1, 3}}; Circle(2) = {{3, 1, 4}};
Circle(3) = {{5, 1, 6}}; Circle(4) = {{6, 1, 7}};
Line(5) = {{2, 5}}; Line(6) = {{7, 4}};
Curve Loop(1) = {{5, 3, 4, 6, -2, -1}};
Plane Surface(1) = {{1}};
Physical Curve("inner", 1) = {{1, 2}};
Physical Curve("outer", 2) = {{3, 4}};
Physical Surface("body", 3) = {{1}};
"""

GRADING = """
Field[1] = Distance; Field[1].PointsList = {{5}};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = {h_contact}; Field[2].SizeMax = {h};
Field[2].DistMin = {zone}; Field[2].DistMax = {zone_end};
Background Field = 2;
Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromCurvature = 0;
"""


def symmetric_mesh(path, h, h_contact=None, zone=0.0, grow=0.1, r_inner=0.25, r_outer=0.5):
    """Write the mirror-symmetric annulus mesh to `path`; return its number of vertices."""
    geo = HALF_GEO.format(h=h, r_inner=r_inner, r_outer=r_outer)
    if h_contact is not None:
        geo += GRADING.format(h=h, h_contact=h_contact, zone=zone, zone_end=zone + grow)
    with open("half.geo", "w") as f:
        f.write(geo)
    subprocess.run(["gmsh", "-2", "-format", "msh22", "half.geo", "-o", "half.msh"], check=True, capture_output=True)
    lines = open("half.msh").read().split("\n")
    i = lines.index("$Nodes")
    nodes = {}
    for l in lines[i + 2:i + 2 + int(lines[i + 1])]:
        w = l.split()
        nodes[int(w[0])] = (float(w[1]), float(w[2]))
    i = lines.index("$Elements")
    elems = [list(map(int, l.split())) for l in lines[i + 2:i + 2 + int(lines[i + 1])]]
    mirror, nid = {}, max(nodes)
    for k, (x, y) in sorted(nodes.items()):
        if abs(x) < 1e-14:
            nodes[k] = (0.0, y)
            mirror[k] = k
        else:
            nid += 1
            mirror[k] = nid
    allnodes = dict(nodes)
    for k, (x, y) in nodes.items():
        if mirror[k] != k:
            allnodes[mirror[k]] = (-x, y)
    out = []
    for e in elems:
        etype, ntags = e[1], e[2]
        tags, vs = e[3:3 + ntags], e[3 + ntags:]
        if etype not in (1, 2):
            continue
        out.append((etype, tags, vs))
        m = [mirror[v] for v in vs]
        if etype == 2:
            m = [m[0], m[2], m[1]]  # keep the orientation positive
        else:
            m = [m[1], m[0]]
        out.append((etype, [tags[0], tags[1] + 100], m))
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 1 \"inner\"\n1 2 \"outer\"\n2 3 \"body\"\n$EndPhysicalNames\n")
        f.write(f"$Nodes\n{len(allnodes)}\n")
        for k in sorted(allnodes):
            f.write(f"{k} {allnodes[k][0]!r} {allnodes[k][1]!r} 0\n")
        f.write(f"$EndNodes\n$Elements\n{len(out)}\n")
        for j, (etype, tags, vs) in enumerate(out, 1):
            f.write(f"{j} {etype} {len(tags)} {' '.join(map(str, tags))} {' '.join(map(str, vs))}\n")
        f.write("$EndElements\n")
    return len(allnodes)

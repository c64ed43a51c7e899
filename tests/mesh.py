"""Mesh tests: the annulus that roller builds (gmsh file or in-process gmsh) has the boundary labels, counts,
area and boundary lengths that an independent reading of the mesh predicts, the same on 1 and 2 ranks,
and bad meshes are refused with a message naming the file.

    mesh.py file MESH.msh   counts from the file parsed here; area and lengths of the inscribed polygons
    mesh.py gmsh            the in-process gmsh mesh at -mesh_h 0.05 (two geometries)
    mesh.py bad             meshes that are not triangulated annuli about the origin, a missing file
    mesh.py mpi             2 ranks give the 1-rank global counts; -partition_view reports the edge cut
"""
import math
import os
import re
import sys

from rollertest import SOURCE, Checker, run

NO_STEPS = ["-mesh_view_info", "-ts_max_steps", "0"]
MESH_LINE = re.compile(r"^mesh: vertices (\d+) cells (\d+) inner_vertices (\d+) outer_vertices (\d+) "
                       r"area (\S+) inner_length (\S+) outer_length (\S+)$", re.M)


def source_path(rel):
    return os.path.join(SOURCE, rel)


def mesh_info(args, nproc=1):
    """Run roller without time steps and return its -mesh_view_info line as a dict, and the whole stdout."""
    _, out, _ = run(NO_STEPS + args, nproc=nproc)
    found = MESH_LINE.findall(out)
    if len(found) != 1:
        raise SystemExit(f"FAIL: expected one 'mesh:' line from roller {' '.join(args)}, got {len(found)}:\n{out}")
    v = found[0]
    info = dict(vertices=int(v[0]), cells=int(v[1]), inner_vertices=int(v[2]), outer_vertices=int(v[3]),
                area=float(v[4]), inner_length=float(v[5]), outer_length=float(v[6]))
    return info, out


def read_msh(path):
    """Independent ASCII gmsh 2.2 / 4.1 reader: physical names, node coordinates, elements with their
    physical tags. Returns (names {name: (dim, tag)}, nodes {id: (x, y)}, elements [(type, tags, nodes)])."""
    with open(path) as f:
        lines = [l.strip() for l in f]
    sections, i = {}, 0
    while i < len(lines):
        if lines[i].startswith("$") and not lines[i].startswith("$End"):
            name = lines[i][1:]
            j = lines.index("$End" + name, i)
            sections[name] = lines[i + 1:j]
            i = j
        i += 1
    version = float(sections["MeshFormat"][0].split()[0])
    names = {}
    for l in sections.get("PhysicalNames", [])[1:]:
        dim, tag, name = l.split(maxsplit=2)
        names[name.strip('"')] = (int(dim), int(tag))
    nodes, elements = {}, []
    if version < 3:
        body = sections["Nodes"]
        for l in body[1:]:
            w = l.split()
            nodes[int(w[0])] = (float(w[1]), float(w[2]))
        for l in sections["Elements"][1:]:
            w = [int(x) for x in l.split()]
            ntags = w[2]
            elements.append((w[1], w[3:3 + ntags][:1], w[3 + ntags:]))
    else:
        # Entities: points "tag x y z nphys phys...", others "tag 6 bbox nphys phys ..."
        ent = sections["Entities"]
        counts = [int(x) for x in ent[0].split()]
        physical, k = {}, 1
        for dim, n in enumerate(counts):
            for _ in range(n):
                w = ent[k].split()
                k += 1
                at = 4 if dim == 0 else 7
                physical[(dim, int(w[0]))] = [int(x) for x in w[at + 1:at + 1 + int(w[at])]]
        body, k = sections["Nodes"], 1
        while k < len(body):
            dim, tag, param, n = (int(x) for x in body[k].split())
            ids = [int(x) for x in body[k + 1:k + 1 + n]]
            for j, node in enumerate(ids):
                w = body[k + 1 + n + j].split()
                nodes[node] = (float(w[0]), float(w[1]))
            k += 1 + 2 * n
        body, k = sections["Elements"], 1
        while k < len(body):
            dim, tag, etype, n = (int(x) for x in body[k].split())
            for l in body[k + 1:k + 1 + n]:
                w = [int(x) for x in l.split()]
                elements.append((etype, physical[(dim, tag)], w[1:]))
            k += 1 + n
    return names, nodes, elements


def expected_from_file(path):
    """What roller must report for a mesh file, computed from the file alone."""
    names, nodes, elements = read_msh(path)
    tag = {g: names[g][1] for g in ("inner", "outer", "body")}
    lines = {g: [e[2] for e in elements if e[0] == 1 and tag[g] in e[1]] for g in ("inner", "outer")}
    triangles = [e[2] for e in elements if e[0] == 2 and tag["body"] in e[1]]
    exp = dict(cells=len(triangles), vertices=len({n for t in triangles for n in t}))
    for g in ("inner", "outer"):
        ids = {n for l in lines[g] for n in l}
        exp[g + "_vertices"] = len(ids)
        exp["r_" + g] = sum(math.hypot(*nodes[n]) for n in ids) / len(ids)
        exp[g + "_length_file"] = sum(math.dist(nodes[a], nodes[b]) for a, b in lines[g])
    return exp


def polygon(n, r):
    """Area and perimeter of the regular n-gon inscribed in the circle of radius r (gmsh spaces the nodes of
    each half circle uniformly, and both halves get the same number)."""
    return 0.5 * n * r * r * math.sin(2 * math.pi / n), 2 * n * r * math.sin(math.pi / n)


def check_geometry(c, info, r_inner, r_outer, label):
    """Area and lengths equal those of the inscribed polygons (to rounding) and lie within 1% of the circles'."""
    a_out, l_out = polygon(info["outer_vertices"], r_outer)
    a_in, l_in = polygon(info["inner_vertices"], r_inner)
    area, circle_area = a_out - a_in, math.pi * (r_outer ** 2 - r_inner ** 2)
    for what, got, exact, smooth in (("area", info["area"], area, circle_area),
                                     ("inner_length", info["inner_length"], l_in, 2 * math.pi * r_inner),
                                     ("outer_length", info["outer_length"], l_out, 2 * math.pi * r_outer)):
        c.check(abs(got - exact) <= 1e-10 * exact, f"{label}: {what} {got:.15g} = inscribed polygons {exact:.15g} (1e-10)")
        c.check(abs(got - smooth) <= 0.01 * smooth and got < smooth, f"{label}: {what} {got:.15g} within 1% below the circle value {smooth:.15g}")


def test_file(c, rel):
    path = source_path(rel)
    exp = expected_from_file(path)
    info, _ = mesh_info(["-dm_plex_filename", path])
    for key in ("vertices", "cells", "inner_vertices", "outer_vertices"):
        c.check(info[key] == exp[key], f"{rel}: {key} {info[key]} = {exp[key]} counted in the file")
    for g in ("inner", "outer"):
        got, want = info[g + "_length"], exp[g + "_length_file"]
        c.check(abs(got - want) <= 1e-12 * want, f"{rel}: {g}_length {got:.15g} = sum of the file's {g} edges {want:.15g}")
    check_geometry(c, info, exp["r_inner"], exp["r_outer"], rel)


def test_gmsh(c):
    h = 0.05
    for r_inner, r_outer in ((0.25, 0.5), (0.2, 0.6)):
        label = f"gmsh -mesh_h {h} -r_inner {r_inner} -r_outer {r_outer}"
        info, _ = mesh_info(["-mesh_h", h, "-r_inner", r_inner, "-r_outer", r_outer])
        for g, r in (("inner", r_inner), ("outer", r_outer)):
            want = 2 * math.pi * r / h
            c.check(abs(info[g + "_vertices"] - want) <= 2, f"{label}: {g}_vertices {info[g + '_vertices']} = 2 pi r / h = {want:.2f} +- 2")
        # Euler's formula for a triangulated annulus: V - E + F = 0 with 3F = 2E - boundary edges.
        boundary = info["inner_vertices"] + info["outer_vertices"]
        c.check(2 * info["vertices"] - info["cells"] == boundary, f"{label}: Euler characteristic 0 (2V - F = boundary edges {boundary})")
        check_geometry(c, info, r_inner, r_outer, label)


def expect_failure(c, args, must_contain, label):
    rc, out, err = run(NO_STEPS + args, check=False)
    text = out + err
    c.check(rc != 0, f"{label}: exits non-zero ({rc})")
    for s in must_contain:
        c.check(s in text, f"{label}: message contains {s!r}")
    print("    " + next((l for l in text.splitlines() if must_contain[-1] in l), "(no such line)"))


def test_bad(c):
    data = lambda name: source_path(os.path.join("tests", "data", name))
    good = source_path("meshes/annulus-h0.05-v41.msh")
    missing = os.path.abspath("no-such-mesh.msh")
    cases = [
        ("square without physical groups", data("square_nogroups.msh"), [], ['no curve physical group named "inner"']),
        ("groups named Gamma_D, Gamma_C, Omega", data("annulus_misnamed.msh"), [], ['"inner"', "Gamma_D"]),
        ("annulus centred at (0.1, 0)", data("annulus_offcentre.msh"), [], ["not on one circle about the origin"]),
        ("quadrilateral cells", data("annulus_quads.msh"), [], ["quadrilateral", "triangles"]),
        ("3-D tetrahedral box", data("box3d.msh"), [], ["dimension 3"]),
        ("missing file", missing, [], ["cannot open"]),
        ("not a mesh file", data("square_nogroups.geo"), [], ["$MeshFormat"]),
        ("-r_inner contradicting the file", good, ["-r_inner", "0.3"], ["-r_inner 0.3", "0.25"]),
    ]
    for label, path, extra, phrases in cases:
        expect_failure(c, ["-dm_plex_filename", path] + extra, [path] + phrases, label)
    expect_failure(c, ["-mesh_h", "0.3"], ["-mesh_h", "0.3"], "-mesh_h wider than the annulus")


def test_mpi(c):
    for label, args in (("msh41 file", ["-dm_plex_filename", source_path("meshes/annulus-h0.05-v41.msh")]),
                        ("in-process gmsh", ["-mesh_h", "0.05"])):
        serial, _ = mesh_info(args)
        for partitioner in ([], ["-petscpartitioner_type", "simple"]):
            name = " ".join([label] + partitioner)
            par, out = mesh_info(args + ["-partition_view"] + partitioner, nproc=2)
            for key in ("vertices", "cells", "inner_vertices", "outer_vertices"):
                c.check(par[key] == serial[key], f"{name}, 2 ranks: {key} {par[key]} = 1 rank {serial[key]}")
            for key in ("area", "inner_length", "outer_length"):
                c.check(abs(par[key] - serial[key]) <= 1e-12 * serial[key], f"{name}, 2 ranks: {key} {par[key]:.15g} = 1 rank {serial[key]:.15g}")
            m = re.search(r"^partition: (\S+) ranks 2 edge_cut (\d+).*?(?: metis_objval (\d+))?$", out, re.M)
            c.check(m is not None, f"{name}: -partition_view prints the edge cut")
            if not m:
                continue
            cut = int(m.group(2))
            c.check(0 < cut < serial["cells"], f"{name}: edge cut {cut} is positive and below the cell count")
            if not partitioner:
                c.check(m.group(1) == "metis" and m.group(3) is not None and int(m.group(3)) == cut,
                        f"{name}: METIS partition, counted cut {cut} = METIS objval {m.group(3)}")
            cells = [int(x) for x in re.findall(r"^partition: rank \d+ cells (\d+)$", out, re.M)]
            c.check(len(cells) == 2 and sum(cells) == serial["cells"] and min(cells) > 0, f"{name}: cells per rank {cells} sum to {serial['cells']}")
            c.check(not any(s in out for s in ("Point Partition", "PetscSF Object", "Point renumbering")), f"{name}: -partition_view does not trigger PETSc's partition dump")


def main():
    mode = sys.argv[1]
    c = Checker(f"mesh {' '.join(sys.argv[1:])}")
    if mode == "file":
        test_file(c, sys.argv[2])
    elif mode == "gmsh":
        test_gmsh(c)
    elif mode == "bad":
        test_bad(c)
    elif mode == "mpi":
        test_mpi(c)
    else:
        raise SystemExit(f"unknown mode {mode}")
    c.close()


if __name__ == "__main__":
    main()

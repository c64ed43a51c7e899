"""Carter's rolling contact scene shared by tests/friction_carter.py (the transient) and tests/steady_rolling.py (the
steady state of -modes): the paper's annulus (r_D = 0.25 < r < r_C = R = 0.5, E = 0.1, nu = 0.49, rho = 1) pressed
to depth 0.002 with mu = 0.8; the graded mesh and Carter's tangential force (Johnson, Contact Mechanics, 8.2)."""
import math
import subprocess

E, NU, RHO, R, R_IN, MU, DEPTH = 0.1, 0.49, 1.0, 0.5, 0.25, 0.8, 0.002
E_STAR = E / (1 - NU**2)

GEO = """
r_i = {r_inner}; r_o = {r_outer}; h = {h};
Point(1) = {{0, 0, 0, h}};
Point(2) = {{r_i, 0, 0, h}}; Point(3) = {{-r_i, 0, 0, h}};
{points}
Circle(1) = {{2, 1, 3}}; Circle(2) = {{3, 1, 2}};
Circle(3) = {{10, 1, 11}}; Circle(4) = {{11, 1, 12}}; Circle(5) = {{12, 1, 13}}; Circle(6) = {{13, 1, 10}};
Curve Loop(1) = {{3, 4, 5, 6}}; Curve Loop(2) = {{1, 2}};
Plane Surface(1) = {{1, 2}};
Physical Curve("inner", 1) = {{1, 2}};
Physical Curve("outer", 2) = {{3, 4, 5, 6}};
Physical Surface("body", 3) = {{1}};
Field[1] = Distance; Field[1].CurvesList = {{3, 4}}; Field[1].NumPointsPerCurve = 4000;
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = {hc}; Field[2].SizeMax = {h};
Field[2].DistMin = {layer}; Field[2].DistMax = {dist_max};
Background Field = 2;
Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromCurvature = 0;
"""


def sector_mesh(path, phi_a, phi_b, hc, h=0.04):
    """The annulus graded to hc within 2 hc of the arc phi_a <= phi <= phi_b of Gamma_C (the point
    (-r_C sin phi, -r_C cos phi): phi from the bottom point toward -x, where the patch moves as theta grows),
    growing to h over 3 (h - hc). gmsh msh 2.2 with the physical groups Roller reads. Gamma_C is four arcs
    (each < pi): the graded arc in two halves, the rest in two."""
    assert 0 < phi_b - phi_a < 2 * math.pi - 0.2
    rest = 2 * math.pi - (phi_b - phi_a)
    phis = [phi_b, 0.5 * (phi_a + phi_b), phi_a, phi_a - 0.5 * rest]  # counterclockwise, as the inner circle
    points = "\n".join(f"Point({10 + k}) = {{{-R * math.sin(p)!r}, {-R * math.cos(p)!r}, 0, h}};" for k, p in enumerate(phis))
    geo = GEO.format(r_inner=R_IN, r_outer=R, h=h, hc=hc, points=points, layer=2 * hc, dist_max=2 * hc + 3 * (h - hc))
    with open(path + ".geo", "w") as f:
        f.write(geo)
    subprocess.run(["gmsh", "-2", "-format", "msh22", path + ".geo", "-o", path], check=True, capture_output=True)


def carter_q(creep, a, mu=MU):
    """Carter's |Q|/(mu P) at the creep |xi - xi_0| (1 beyond full slip)."""
    x = min(abs(creep) * R / (mu * a), 1.0)
    return 1 - (1 - x) ** 2

# Mesh tests (src/mesh.c, src/partition.c): labels, counts, area and lengths against an independent reading
# of the mesh; bad meshes refused; 1 and 2 ranks agree. The .msh files are committed: meshes/annulus.geo at
# h = 0.05 (gmsh -2 -format msh22|msh41 -setnumber h 0.05) and the bad ones from tests/data/*.geo.
roller_test(mesh_file_msh22 mesh.py LABELS quick ARGS file meshes/annulus-h0.05-v22.msh TIMEOUT 60)
roller_test(mesh_file_msh41 mesh.py LABELS quick ARGS file meshes/annulus-h0.05-v41.msh TIMEOUT 60)
roller_test(mesh_gmsh mesh.py LABELS quick ARGS gmsh TIMEOUT 60)
roller_test(mesh_bad mesh.py LABELS quick ARGS bad TIMEOUT 120)
roller_test(mesh_mpi mesh.py LABELS mpi ARGS mpi PROCESSORS 2 TIMEOUT 120)
roller_test(geometry_curved geometry_curved.py LABELS quick)

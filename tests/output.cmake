# Output tests (src/output.c): the XDMF index parses and every HDF5 dataset it names exists with the stated
# shape and type; the fields are right (lab displacement, R and alpha from the written displacement, |sigma|);
# a killed run leaves only .part files with a valid index, a complete run none.
roller_test(output_xdmf output_xdmf.py LABELS quick TIMEOUT 180)
roller_test(output_xdmf_mpi output_xdmf.py LABELS mpi ARGS mpi PROCESSORS 2 TIMEOUT 180)
# -monitor_surface_csv: the lab-frame orders of the radial displacement of Gamma_C (the sound's source): ur0 = R, the
# orders against an independent quadrature of the HDF5 output, the flattening's signs, 2 ranks the same rows.
roller_test(surface_orders surface_orders.py LABELS quick mpi PROCESSORS 2 TIMEOUT 300)

"""1 rank and 2 ranks give the same frictional time series (issue 14): the feeder (jobs/feed.yaml: rolling with
Coulomb friction mu = 0.8 and 1 % creep) on a coarse mesh to t = 2; the contact patch moves across the partition
boundary. Every rank holds the same copy of the Gamma_C data and solves the same small friction problem
(docs/friction.md section 3), so the stick and slip counts are identical at every step and the forces, the
torque, the works and the displacements agree to 1e-10 of their largest values."""
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("friction_mpi")
d = []
for n in (1, 2):
    run(["-options_file", f"{SOURCE}/jobs/feed.yaml", "-mesh_h", 0.05, "-mesh_h_contact", 0.0112, "-mesh_contact_layer", 0.0224, "-ts_max_time", 2.0, "-quiet",
         "-monitor_csv", f"feed_np{n}.csv"], nproc=n)
    d.append(read_csv(f"feed_np{n}.csv"))
c.check(d[0]["slip_nodes"].max() > 0 and d[0]["stick_nodes"].max() > 0, f"stick (up to {d[0]['stick_nodes'].max():.0f}) and slip (up to {d[0]['slip_nodes'].max():.0f}) nodes occur")
for col in ("contact_nodes", "stick_nodes", "slip_nodes"):
    c.check(np.array_equal(d[0][col], d[1][col]), f"{col}: identical at every step on 1 and 2 ranks")
for col in ("R", "alpha", "energy", "contact_force", "friction_force", "shaft_torque", "friction_work", "shaft_work", "sheet_work"):
    scale = np.abs(d[0][col]).max()
    diff = np.abs(d[0][col] - d[1][col]).max() / scale
    c.check(diff < 1e-10, f"{col}: agrees to {diff:.1e} (relative to max {scale:.3e}) < 1e-10")
c.close()

"""Restart. A checkpoint holds the full state (xi^k, xi^{k-1}, xi^{k-2}, k, t; theta and the obstacle are
functions of t): an interrupted-then-restarted run gives the same CSV rows as an uninterrupted one, to the
last digit. SIGTERM (what a batch scheduler sends first) finishes the step, writes the checkpoint and exits
cleanly with a message saying how to restart. Checkpoints are written to a temporary name and renamed,
so even a SIGKILL in the middle of the run leaves a readable latest checkpoint.

Discretization: the free and contact restarts run Roller's default (P2 curved, the extrapolated Coriolis
velocity, which reads xi^{k-3} and so needs the full history from the checkpoint, dt from -ts_phase_error:
0.00384 for t <= 4) on -mesh_h 0.05; the friction restart (rolling at omega = pi/10 over a sheet at 0.155 with
mu = 0.8) also continues the cumulative works of the CSV. The SIGTERM/SIGKILL runs (to t = 60 on -mesh_h 0.0125) pin what they
were written with, P1, -ts_dt 0.0125, backward Coriolis velocity: 4800 steps, where the defaults would take
about 60,000 P2 steps. The graded-mesh restart (-mesh_h 0.05 -mesh_h_contact 0.025) restarts without mesh options."""
import os
import signal
import subprocess
import time

from rollertest import EXE, Checker, run


def wait_for(path, rows=0, limit=120.0):
    """Wait until path exists (with more than `rows` lines): the run is stepping, whatever the load."""
    start = time.time()
    while time.time() - start < limit:
        if os.path.exists(path) and (rows == 0 or sum(1 for _ in open(path)) > rows):
            return
        time.sleep(0.1)

c = Checker("restart")
contact = ["-obstacle", "-obstacle_speed", "0.05", "-obstacle_depth", "0.01"]
# friction: the cumulative shaft, sheet and friction works and the shaft torque continue from the checkpoint
friction = contact + ["-friction", "0.8", "-sheet_speed", "0.155", "-viscosity", "0.0115"]
# the generalized Maxwell rubber: its branches' internal variables (z_i and K_d z_i of the kept levels) continue from
# the checkpoint; rolling with friction (the trapezoidal rule, z at half levels) and free with dmf (z at two levels)
maxwell = ["-rubber", "maxwell", "-rubber_loss_factor", "0.1", "-rubber_band", "0.1,10"]
scenes = (("free", []), ("contact", contact + ["-damping", "1"]), ("friction", friction),
          ("maxwell", contact + ["-friction", "0.8", "-sheet_speed", "0.155"] + maxwell), ("maxwell_dmf", maxwell + ["-ts_scheme", "dmf"]))
for scene, extra in scenes:
    base = ["-mesh_h", "0.05", "-ts_max_time", "4", "-quiet"] + extra
    cm = (lambda tag: ["-contact_monitor", f"ascii:{scene}_{tag}_contact.csv:ascii_csv"]) if "-obstacle" in extra else (lambda tag: [])
    run(base + ["-monitor_csv", f"{scene}_full.csv"] + cm("full"))
    run(base + ["-ts_max_steps", "150", "-checkpoint_every", "50", "-checkpoint", f"{scene}.h5", "-monitor_csv", f"{scene}_cut.csv"])
    run(base + ["-restart", f"{scene}.h5", "-monitor_csv", f"{scene}_cut.csv"] + cm("restart"))
    same = open(f"{scene}_full.csv").read() == open(f"{scene}_cut.csv").read()
    c.check(same, f"{scene}: stopped at step 150, restarted from the step-150 checkpoint: CSV identical to the uninterrupted run")
    if "-obstacle" in extra:  # the contact monitor after a restart: its first rows are the uninterrupted run's (not 0 nodes)
        full = open(f"{scene}_full_contact.csv").read().splitlines()
        restarted = open(f"{scene}_restart_contact.csv").read().splitlines()
        first = restarted[1] if len(restarted) > 1 else ""
        same = next((row for row in full if row.split(",")[0] == first.split(",")[0]), None) == first and restarted[1:] == full[-(len(restarted) - 1):]
        c.check(same and first.startswith("151,"), f"{scene}: the restarted contact monitor's first row (step {first.split(',')[0]}) and all after it equal the uninterrupted run's")

# a graded mesh: the checkpoint holds -mesh_h with its -mesh_h_contact and -mesh_contact_layer, so a restart
# that gives none of them rebuilds the same mesh (another would have other dofs and be refused)
mesh = ["-mesh_h", "0.05", "-mesh_h_contact", "0.025", "-mesh_contact_layer", "0.03"]
base = ["-ts_max_time", "4", "-quiet", "-obstacle", "-obstacle_speed", "0.05", "-obstacle_depth", "0.01", "-damping", "1"]
run(base + mesh + ["-monitor_csv", "graded_full.csv"])
run(base + mesh + ["-ts_max_steps", "150", "-checkpoint_every", "50", "-checkpoint", "graded.h5", "-monitor_csv", "graded_cut.csv"])
run(base + ["-restart", "graded.h5", "-monitor_csv", "graded_cut.csv"])
c.check(open("graded_full.csv").read() == open("graded_cut.csv").read(), "graded mesh: restarted without the mesh options (from the checkpoint's): CSV identical to the uninterrupted run")

# SIGTERM: clean stop with a checkpoint, then a restart that ends where the uninterrupted run ends
base = ["-mesh_h", "0.0125", "-degree", "1", "-ts_dt", "0.0125", "-coriolis_velocity", "backward", "-ts_max_time", "60", "-quiet"]
run(base + ["-monitor_csv", "term_full.csv"])
proc = subprocess.Popen([EXE] + base + ["-checkpoint", "term.h5", "-monitor_csv", "term_cut.csv"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
wait_for("term_cut.csv.part", rows=200)
proc.send_signal(signal.SIGTERM)
out, err = proc.communicate()
c.check(proc.returncode == 0 and "-restart term.h5" in out and os.path.exists("term.h5"), f"SIGTERM: exit {proc.returncode}, message: {out.strip()[:160]}")
run(base + ["-restart", "term.h5", "-monitor_csv", "term_cut.csv"])
c.check(open("term_full.csv").read() == open("term_cut.csv").read(), "SIGTERM + restart: CSV identical to the uninterrupted run")

# SIGKILL while checkpointing every step: the latest checkpoint is always complete (an earlier run's file removed first:
# the wait below must see this run's)
for stale in ("kill.h5", "kill.h5.tmp"):
    if os.path.exists(stale):
        os.remove(stale)
proc = subprocess.Popen([EXE] + base + ["-checkpoint", "kill.h5", "-checkpoint_every", "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
wait_for("kill.h5")
time.sleep(0.5)
proc.kill()
proc.wait()
code, out, err = run(base + ["-restart", "kill.h5", "-monitor_csv", "kill.csv"], check=False)
c.check(code == 0 and os.path.exists("kill.csv"), f"SIGKILL during checkpointing: the latest checkpoint restarts (exit {code})")
c.close()

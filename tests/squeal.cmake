# The squeal CEA of the paper's roller (docs/squeal.md section 4.2): mu = 0 conservative, the steady sliding forces, the
# order-1 backward pair unstable at mu = 0.8, the linear onset in mu (no threshold: unstable at mu = 0.3 too),
# sign reversal with the slip, without rotation the coalescence of the order-3 pair at mu_c (bisection); coarse
# graded mesh, about 40 s of CPU
roller_test(squeal_quick squeal_quick.py LABELS quick TIMEOUT 300)
# The transient (DMF, co-rotating frame, Coulomb every step) seeded on the steady state plus the order-1 backward
# mode at mu = 0.3 against the CEA's growth rate (5 %) and frequency (2 %), and mu = 0.8 leaving the CEA's regime;
# about 3 min of CPU (docs/squeal.md section 4.2)
roller_test(squeal_transient squeal_transient.py LABELS long TIMEOUT 1800)
# The steady rolling state with stick and slip zones solved as one static problem (-modes -modes_nev 0, the lab
# frame) against Carter: Coulomb's law at every node, |Q|/(mu P) within 0.02, the stick zone at the leading edge
# with Carter's width, driving and braking, 1 and 2 ranks (docs/squeal.md section 3.2; about 15 s)
roller_test(steady_rolling steady_rolling.py LABELS quick PROCESSORS 2 TIMEOUT 300)
# The one-command squeal report (python3 -m rollerreport.run, docs/squeal.md section 9.2) on the printer roller (SI,
# its own friction law) and the feeder (coarse mesh): the CEA, a 2 x 2 map on 2 ranks, the seeded transient, the
# report; checks the verdict against modes.csv, the transient's frequency (2 %), the WAV's loudest line at the pitch
# (2 %), the map, spectrogram and GIF; about 6-8 min on 2 cores
roller_test(squeal_report squeal_report.py LABELS long PROCESSORS 2 TIMEOUT 2400)
# The steady rolling state over Carter's whole creep curve: 24 creeps from free rolling (Q = 0) to full slip
# (|Q| = mu P), separate runs two at a time: every one converges, Coulomb's law at every node, |Q|/(mu P) within 0.02
# of Carter's, the stick zone at the leading edge (docs/squeal.md section 3). quick: h_c = 0.003 (about 50 s of CPU);
# long: h_c = 0.0007, where the solver before the fix stopped at three of four creeps near free rolling (150 s of CPU)
roller_test(steady_sweep steady_sweep.py LABELS quick PROCESSORS 2 TIMEOUT 600)
roller_test(steady_sweep_long steady_sweep.py LABELS long ARGS long PROCESSORS 2 TIMEOUT 1800)
# The CEA about a rolling state with a stick zone (the feeder, its own damping, the default slip difference box) on
# contact meshes 0.0112, 0.0056, 0.0028 at xi = 0.12, 0.13 and 0.135: the order-1 backward pair's growth converges,
# -modes_stick_margin frees exactly the marginal stick nodes, and at all three creeps the seed's response (coarse
# mesh; at 0.13 on two meshes, agreeing within 10 %) grows at the converged CEA's rate (20 %, frequency 1 %)
# (docs/squeal.md 4.4.4; about 25 min of CPU)
roller_test(squeal_stick squeal_stick.py LABELS long TIMEOUT 3600)

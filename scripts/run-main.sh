#!/usr/bin/env bash
# The main job: the rolling-contact scene (docs/model.md section 5, last row; paper figure 9) with the
# accurate default discretization (-ts_view prints it). Installs what is missing, builds, runs, and leaves in results/main/:
#   roller.csv (one row per step), roller.h5 + roller.xmf (fields, open the .xmf in ParaView),
#   sigma.png (|sigma| on the deformed roller in the lab frame), R.png and alpha.png (time series).
# Extra arguments are passed to roller, e.g. bash scripts/run-main.sh -mesh_h 0.0125 -ts_dt 0.0125
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
bash "$root/scripts/build.sh"
out="$root/results/main"
mkdir -p "$out"
# One rank by default: on a 2-core machine the serial Cholesky factor is the fastest (docs/performance.md,
# strong scaling); ROLLER_NP=2 bash scripts/run-main.sh runs it on two ranks (METIS partition, MUMPS).
nproc_run=${ROLLER_NP:-1}
mpiexec -n "$nproc_run" "$root/build/roller" -options_file "$root/jobs/rolling.yaml" \
  -ts_max_time 20 -ts_view \
  -monitor_csv "$out/roller.csv" -output "$out/roller.h5" -output_every 200 "$@"
PYTHONPATH="$root/scripts" /usr/bin/python3 -m rollerplots.fields "$out/roller.h5" --times 5 10 15 20 --out "$out/sigma.png"
PYTHONPATH="$root/scripts" /usr/bin/python3 -m rollerplots.series --quantity R --out "$out/R.png" --label rolling "$out/roller.csv"
PYTHONPATH="$root/scripts" /usr/bin/python3 -m rollerplots.series --quantity alpha --out "$out/alpha.png" --label rolling "$out/roller.csv"
echo "run-main: results in $out"
ls -la "$out"

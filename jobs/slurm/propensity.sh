#!/bin/bash
# Roller, the squeak report's propensity study (docs/squeal.md 9.4) as Slurm job arrays: the report's table of cases
# (propensity_cases.csv, a Latin hypercube) run as two arrays of sliced maps -- every case's start from rest on the
# reduced model (transient_sweep.sbatch, -sweep_cases, each case's series kept) and, when the scene's own CEA ran, every
# case's CEA (sweep.sbatch) -- merged into the report's folder, then the report classifies them and writes the page.
#   PYTHONPATH=scripts python3 -m rollerreport.run jobs/printer_roller.yaml results/printer --parts cea,mesh,basis,stickslip
#   jobs/slurm/propensity.sh jobs/printer_roller.yaml results/printer 16      (from the repository root: 16 tasks each)
# The first command writes the folder's basis, the scene's CEA and its start from rest; this one writes the table
# (rollerreport.run --parts propensity_table, seconds), submits the arrays, the merges and the report as dependent jobs.
# Options after the task count go to every roller run of the arrays (e.g. the propensity's mesh, as --propensity-options
# gives it to the report; then give the report the same). Environment: ROLLER, PYTHON, NEV (default 40), PERIODS
# (default 40), SBATCH_ARGS (e.g. "--time=08:00:00").
set -euo pipefail
scene=${1:?usage: propensity.sh SCENE.yaml REPORT_DIR TASKS [roller options]}
out=${2:?usage: propensity.sh SCENE.yaml REPORT_DIR TASKS [roller options]}
tasks=${3:?usage: propensity.sh SCENE.yaml REPORT_DIR TASKS [roller options]}
shift 3
PYTHON=${PYTHON:-python3}
NEV=${NEV:-40}
PERIODS=${PERIODS:-40}
report=(env PYTHONPATH=scripts "$PYTHON" -m rollerreport.run "$scene" "$out" --propensity-nev "$NEV" --propensity-periods "$PERIODS")
"${report[@]}" --parts propensity_table
t_end=$(env PYTHONPATH=scripts "$PYTHON" -c "import json; print(json.load(open('$out/propensity_table.json'))['run_time'])")
basis="$out/basis.h5"
[ -f "$out/propensity_basis.h5" ] && basis="$out/propensity_basis.h5"
n=$(($(grep -cv '^#' "$out/propensity_cases.csv") - 1))
mkdir -p "$out/propensity"
common=(-options_file "$scene" -sweep_cases "$out/propensity_cases.csv" -quiet "$@")
runs=$(OUT="$out/runs" sbatch --parsable ${SBATCH_ARGS:-} --array=0-$((tasks - 1)) jobs/slurm/transient_sweep.sbatch "${common[@]}" \
  -rom -rom_input "$basis" -ts_max_time "$t_end" -sweep_monitor_csv "$out/propensity/series.csv" -sweep_fit friction_force)
deps=afterok:$(sbatch --parsable --dependency=afterok:"$runs" \
  --wrap "env PYTHONPATH=scripts $PYTHON -m rollertools.merge_sweep $out/runs/part_*.csv -o $out/propensity_runs.csv --cases $n")
if grep -q '"status": "ok"' <(env PYTHONPATH=scripts "$PYTHON" -c "import json; print(json.dumps(json.load(open('$out/journal.json'))['parts'].get('cea', {})))"); then
  cea=$(OUT="$out/cea" sbatch --parsable ${SBATCH_ARGS:-} --array=0-$((tasks - 1)) jobs/slurm/sweep.sbatch "${common[@]}" -modes_nev "$NEV")
  deps=$deps:$(sbatch --parsable --dependency=afterok:"$cea" \
    --wrap "env PYTHONPATH=scripts $PYTHON -m rollertools.merge_sweep $out/cea/part_*.csv -o $out/propensity_cea.csv --cases $n")
fi
sbatch --dependency="$deps" --wrap "${report[*]} --parts propensity,sound,animation"

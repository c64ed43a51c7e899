#!/bin/bash
# Submit a chain of LINKS dependent jobs of jobs/slurm/chain.sbatch (each starts when the one before ended
# successfully, --dependency=afterok) for one long run; the roller options follow LINKS. From the repository root:
#   RUN=feed jobs/slurm/chain.sh 6 -options_file jobs/feed.yaml -ts_max_time 400
# Environment: RUN (the run's name: results/$RUN holds its checkpoint, CSV and logs), and what chain.sbatch reads
# (ROLLER, LAUNCH, OUT, MARGIN, WALL); SBATCH_ARGS is passed to every sbatch (e.g. "--ntasks=8 --time=08:00:00").
# Submit more links later with the same RUN: the first new one depends on nothing and resumes from the checkpoint.
set -euo pipefail
[ $# -ge 1 ] && [ "$1" -ge 1 ] 2>/dev/null || { echo "usage: $0 LINKS [roller options]" >&2; exit 1; }
links=$1
shift
export RUN=${RUN:-chain}
dep=()
for ((i = 1; i <= links; ++i)); do
  # shellcheck disable=SC2086
  jid=$(sbatch --parsable --export=ALL ${SBATCH_ARGS:-} "${dep[@]}" jobs/slurm/chain.sbatch "$@")
  echo "link $i/$links: job $jid"
  dep=(--dependency=afterok:"$jid")
done

#!/usr/bin/env bash
# The paper's figures 3-9 from its own set-ups, jobs/paper/fig3.yaml ... fig9.yaml (P1, h = dt = 0.0125,
# backward Coriolis velocity, projected CG for the contact figures), into docs/figures/
# (docs/validation.md section 6 lists them with their commands).
# Usage: bash scripts/figures.sh [free|contact|all]   (runs build/roller; build first with scripts/build.sh)
# Time on the 2-core development machine: about 3 minutes for all.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
roller="$root/build/roller"
py=/usr/bin/python3
export PYTHONPATH="$root/scripts${PYTHONPATH:+:$PYTHONPATH}"
fig="$root/docs/figures"
work="$root/results/figures"
mkdir -p "$fig" "$work"
what="${1:-all}"

if [ "$what" = free ] || [ "$what" = all ]; then
  # exact axisymmetric reference (Table 1 values) for figures 3-4
  $py -m rollerref.axisym --scheme exact --t-end 20 --dt-out 0.0125 --out "$work/reference.csv"
  # figures 3, 4 (jobs/paper/fig3.yaml = fig4.yaml): dx = dt = 0.0125 * 2^(i-1), i = 1..4
  labels=()
  for h in 0.0125 0.025 0.05 0.1; do
    "$roller" -options_file "$root/jobs/paper/fig3.yaml" -mesh_h $h -ts_dt $h -quiet -monitor_csv "$work/mesh_h$h.csv"
    labels+=(--label "dx = dt = $h" "$work/mesh_h$h.csv")
  done
  for q in R alpha; do
    $py -m rollerplots.series --quantity $q --out "$fig/fig$([ $q = R ] && echo 3 || echo 4)_$q.png" \
      --title "no obstacle, mesh study (paper figure $([ $q = R ] && echo 3 || echo 4))" "${labels[@]}" \
      --reference "$work/reference.csv" --reference-label "exact axisymmetric"
  done
  # figures 5, 6 (jobs/paper/fig5.yaml = fig6.yaml): E = 0.05, 0.1, 0.2
  labels=()
  for E in 0.05 0.1 0.2; do
    "$roller" -options_file "$root/jobs/paper/fig5.yaml" -young $E -quiet -monitor_csv "$work/young$E.csv"
    labels+=(--label "E = $E" "$work/young$E.csv")
  done
  $py -m rollerplots.series --quantity R --out "$fig/fig5_R.png" --title "stiffness study (paper figure 5)" "${labels[@]}"
  $py -m rollerplots.series --quantity alpha --out "$fig/fig6_alpha.png" --title "stiffness study (paper figure 6)" "${labels[@]}"
  # figure 7 (jobs/paper/fig7.yaml): resonance, and the unperturbed rotation (the paper repeats figure 4)
  "$roller" -options_file "$root/jobs/paper/fig7.yaml" -quiet -monitor_csv "$work/resonance.csv"
  "$roller" -options_file "$root/jobs/paper/fig7.yaml" -theta_a 0 -quiet -monitor_csv "$work/steady.csv"
  $py -m rollerplots.series --quantity alpha --out "$fig/fig7_alpha.png" --title "perturbed rotation (paper figure 7)" \
    --label "theta = omega t + 0.001 cos(2 pi t / 9.75)" "$work/resonance.csv" --label "theta = omega t" "$work/steady.csv"
fi

if [ "$what" = contact ] || [ "$what" = all ]; then
  # figures 8 (jobs/paper/fig8.yaml, compression) and 9 (fig9.yaml, rolling): |sigma| on the deformed
  # roller, lab frame
  for scene in compression rolling; do
    yaml=$([ $scene = compression ] && echo fig8 || echo fig9)
    "$roller" -options_file "$root/jobs/paper/$yaml.yaml" -quiet -monitor_csv "$work/$scene.csv" -output "$work/$scene.h5" -output_every 80
    $py -m rollerplots.fields "$work/$scene.h5" --times 2 5 10 20 --out "$fig/${scene}_sigma.png"
  done
  $py -m rollerplots.series --quantity contact_force --out "$fig/contact_force.png" --title "total contact force" \
    --label "compression (omega = 0)" "$work/compression.csv" --label "rolling (omega = pi/10)" "$work/rolling.csv"
fi
echo "figures: $fig"

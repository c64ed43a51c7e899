#!/usr/bin/env bash
# The quick test suite: install what is missing, build, run every test labelled quick, mpi (2 ranks) or unit (C unit tests) with ctest.
# Exits non-zero on any failure. Other labels: bash scripts/test.sh -L long (or hard, mpi).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
bash "$root/scripts/build.sh"
cd "$root/build"
if [ $# -eq 0 ]; then set -- -L 'quick|mpi|unit'; fi
ctest --output-on-failure -j "$(nproc)" "$@"

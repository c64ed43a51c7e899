#!/usr/bin/env bash
# The C sources follow .clang-format (PETSc's style): fails, listing the places, on any unformatted line.
# To format in place: clang-format -i $(git ls-files 'src/*.[ch]' 'include/*.h' 'tests/unit/*.[ch]')
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
mapfile -t files < <(git ls-files 'src/*.[ch]' 'include/*.h' 'tests/unit/*.[ch]' 2>/dev/null || find src include tests/unit -name '*.[ch]' 2>/dev/null)
clang-format --dry-run -Werror "${files[@]}"
echo "format-check: ${#files[@]} files follow .clang-format"

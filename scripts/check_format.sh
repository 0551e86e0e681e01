#!/usr/bin/env bash
# The C style check (docs/DESIGN.md, "Code style"): every tracked C and C++ source as
# .clang-format formats it; a file that differs is named with its first differing lines and
# the check fails. Fix with: git ls-files '*.c' '*.h' '*.cpp' | xargs clang-format -i
# Then the function length (scripts/check_function_length.py): every function of the product
# code (cli/, common/, methods/, api/) under 60 lines, but the few its ALLOWED list names.
set -euo pipefail
cd "$(dirname "$0")/.."
git ls-files -z '*.c' '*.h' '*.cpp' | xargs -0 clang-format --dry-run -Werror --ferror-limit=3
echo "check_format: $(git ls-files '*.c' '*.h' '*.cpp' | wc -l) files formatted as .clang-format says"
python3 scripts/check_function_length.py

# Sourced by scripts/check_lean.sh and scripts/pack_lean.sh: what they count as the
# C runtime, the libraries every Linux machine has (matched against ldd's names),
# which check_lean.sh does not count and pack_lean.sh does not copy.
# shellcheck shell=bash disable=SC2034
lean_runtime='^(linux-vdso\.so|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so)'

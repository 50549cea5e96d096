#!/usr/bin/env bash
# Regenerates include/halfwing.h with the pinned cbindgen, or with --check fails when the
# committed header differs from what the code generates.
set -euo pipefail
cd "$(dirname "$0")/.."
want="0.29.4"
if ! have=$(cbindgen --version 2>/dev/null) || [ "$have" != "cbindgen $want" ]; then
  echo "gen-header: needs cbindgen $want (have: ${have:-none}); install it with" >&2
  echo "  cargo install cbindgen --locked --version $want" >&2
  exit 2
fi
# cbindgen writes constants, then types, then functions; scripts/header-sections.awk regroups
# them by topic (each section a Doxygen group under a banner, each type and enumeration's
# constants before the first function using them).
# Writes the header to $1, which is left alone on failure.
generate() {
  local raw laid_out status=0
  raw=$(mktemp)
  laid_out=$(mktemp)
  cbindgen --config cbindgen.toml --crate halfwing --output "$raw" --quiet &&
    awk -f scripts/header-sections.awk "$raw" >"$laid_out" || status=1
  [ "$status" = 0 ] && cp "$laid_out" "$1"
  rm -f "$raw" "$laid_out"
  [ "$status" = 0 ] || exit 1
}
if [ "${1:-}" = "--check" ]; then
  tmp=$(mktemp)
  trap 'rm -f "$tmp"' EXIT
  generate "$tmp"
  if ! diff -u include/halfwing.h "$tmp"; then
    echo "gen-header: include/halfwing.h is stale; run scripts/gen-header.sh and commit it" >&2
    exit 1
  fi
  echo "gen-header: include/halfwing.h is up to date"
else
  generate include/halfwing.h
fi
# Every name the header gives C (macros and type names) starts with hw_ / HW_ (DESIGN.md): a
# public Rust item that slipped in must be excluded in cbindgen.toml.
if stray=$(grep -E '^#define [A-Za-z_]+|^typedef [a-z_0-9]+ ([A-Za-z_]+ )?[A-Za-z_]+;|^} [A-Za-z_]+;' include/halfwing.h |
  grep -vE '^#define (HW_|HALFWING_H)|^typedef [a-z_0-9]+ ([A-Za-z_]+ )?hw_[a-z0-9_]+;|^} hw_[a-z0-9_]+;'); then
  echo "gen-header: names without the hw_/HW_ prefix in include/halfwing.h:" >&2
  echo "$stray" >&2
  exit 1
fi
# Each enumeration's constants carry its type's name (hw_normal_weighting:
# HW_NORMAL_WEIGHTING_ANGLE), so a value and its family are found from either. The one exception
# is hw_status: HW_OK and HW_ERR_*, the spelling C libraries give status codes.
if misnamed=$(grep -rhoE 'pub const HW_[A-Z0-9_]+: hw_[a-z0-9_]+' src/ffi |
  awk '{ name = $3; sub(/:$/, "", name); type = toupper($4)
         if ($4 != "hw_status" && index(name, type "_") != 1) print name " (" $4 ")" }' | grep .); then
  echo "gen-header: enumeration constants not prefixed by their type's name:" >&2
  echo "$misnamed" >&2
  exit 1
fi

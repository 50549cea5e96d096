#!/usr/bin/env bash
# Builds the API references, failing on any warning:
#   the C and C++ reference (Doxygen, docs/Doxyfile) into build/docs/html/index.html
#   the Rust reference (rustdoc) into target/doc/halfwing/index.html
# `scripts/docs.sh c` or `scripts/docs.sh rust` builds one of them.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

what=${1:-all}
if [ "$what" = all ] || [ "$what" = c ]; then
  if ! command -v doxygen >/dev/null; then
    echo "docs: doxygen is missing; as root: apt-get install -y --no-install-recommends doxygen" >&2
    exit 1
  fi
  export HALFWING_DOCS_OUTPUT=${HALFWING_DOCS_OUTPUT:-build/docs}
  mkdir -p "$HALFWING_DOCS_OUTPUT"
  doxygen docs/Doxyfile
  echo "docs: $HALFWING_DOCS_OUTPUT/html/index.html"
fi
if [ "$what" = all ] || [ "$what" = rust ]; then
  RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --quiet
  echo "docs: target/doc/halfwing/index.html"
fi

#!/usr/bin/env bash
# Makes sure what the demo or the tests need is installed (Debian 12 with a Rust toolchain).
# As root it installs what is missing; otherwise it prints the exact command and stops.
#   scripts/setup.sh demo   cmake, a C/C++ compiler, GLFW, OpenGL headers, Xvfb and Mesa (the viewer)
#   scripts/setup.sh test   also CGAL, OpenMesh, libpng (screenshot checks), pkg-config, doxygen
#                           (the API reference) and cbindgen
set -euo pipefail

what=${1:-test}
cbindgen_version="0.29.4"
packages=(cmake pkg-config g++ make libglfw3-dev libgl-dev xvfb xauth libgl1-mesa-dri)
if [ "$what" = "test" ]; then
  packages+=(libcgal-dev libopenmesh-dev libpng-dev doxygen)
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  command="apt-get update && apt-get install -y --no-install-recommends ${missing[*]}"
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: missing Debian packages; run as root:" >&2
    echo "  $command" >&2
    exit 1
  fi
fi

if [ "$what" = "test" ] && [ "$(cbindgen --version 2>/dev/null)" != "cbindgen $cbindgen_version" ]; then
  command="cargo install cbindgen --locked --version $cbindgen_version"
  if [ "$(id -u)" = 0 ]; then
    echo "setup: $command"
    $command --quiet
  else
    echo "setup: cbindgen $cbindgen_version is needed to check the header; run:" >&2
    echo "  $command" >&2
    exit 1
  fi
fi

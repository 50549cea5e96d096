#!/usr/bin/env bash
# Builds halfwing and the viewer with CMake and opens the viewer on the bundled model
# (examples/data/hole_capsule.off, boundary loops highlighted). Without a display ($DISPLAY
# unset) it renders one frame headless under Xvfb and prints where the PNG went.
#   scripts/demo.sh [model.obj|.off|.ply] [viewer options, e.g. --keys 1N]
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

scripts/setup.sh demo
build=build/demo
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFWING_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target halfwing_viewer
viewer="$build/examples/halfwing_viewer"

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec "$viewer" "$@"
fi
shot="$PWD/$build/halfwing_viewer.png"
echo "demo: no display; rendering one frame headless with Xvfb"
xvfb-run -a -s "-screen 0 1024x768x24" "$viewer" "$@" --screenshot "$shot"
echo "demo: wrote $shot"

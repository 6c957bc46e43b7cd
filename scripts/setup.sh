#!/usr/bin/env bash
# The two set-up commands of the README:
#   scripts/setup.sh run [MODEL]   install what is missing, build, start the GUI (bundled sample
#                                  project when no MODEL is given)
#   scripts/setup.sh test          install what is missing, build, run every test (GUI tests in
#                                  a virtual X server) and print CTest's summary
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
command="${1:-}"
shift || true

usage() {
    sed -n '2,6p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
}

case "$command" in
run)
    "$root/scripts/install-deps.sh"
    "$root/scripts/build.sh"
    gui="$build/bin/stratamesh"
    if [[ ! -x "$gui" ]]; then
        echo "setup: $gui was not built" >&2
        exit 1
    fi
    if [[ -z "${DISPLAY:-}" && -z "${WAYLAND_DISPLAY:-}" ]]; then
        echo "setup: no display; use a desktop session (or xvfb-run -a $gui)" >&2
        exit 1
    fi
    # Without a MODEL the window opens its bundled sample project.
    exec "$gui" "$@"
    ;;
test)
    "$root/scripts/install-deps.sh"
    "$root/scripts/build.sh"
    jobs="$(nproc 2>/dev/null || echo 2)"
    # One virtual X server for the whole run: GUI tests need a display, the others ignore it.
    xvfb-run -a -s "-screen 0 1600x1000x24" \
        ctest --test-dir "$build" --output-on-failure -j "$jobs" "$@"
    ;;
*)
    usage >&2
    exit 2
    ;;
esac

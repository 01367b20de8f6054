#!/bin/sh
# Runs a command with an X display, which SFML needs for OpenGL even when it
# draws off screen: the current DISPLAY if there is one, else a private Xvfb
# started by xvfb-run (Debian's xvfb and xauth). Exit status 77 (ctest's
# "skipped" here) when there is neither.
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
if command -v xvfb-run >/dev/null 2>&1; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24 -nolisten tcp" "$@"
fi
echo "with_display.sh: no DISPLAY and no xvfb-run (apt-get install xvfb xauth): skipped" >&2
exit 77

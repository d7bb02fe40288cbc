#!/bin/sh
# xvfb_run.sh WxHxD COMMAND [ARG...]: runs COMMAND under an Xvfb of its own whose display
# number the server picks itself (-displayfd). `xvfb-run -a` chooses the number from lock
# files before starting the server, so two tests starting at once could race for one display
# and the loser's client failed to open it (seen once in CI).
screen=$1
shift
dir=$(mktemp -d "${TMPDIR:-/tmp}/kinema-xvfb.XXXXXX") || exit 1
# No -auth: the server is private to this run (its number is known only here) and local only.
Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp 3>"$dir/display" 2>"$dir/log" &
xvfb=$!
tries=0
while ! grep -q '[0-9]' "$dir/display" 2>/dev/null; do
  if ! kill -0 "$xvfb" 2>/dev/null; then
    echo "xvfb_run.sh: Xvfb failed to start: $(tail -n 1 "$dir/log")" >&2
    rm -rf "$dir"
    exit 1
  fi
  tries=$((tries + 1))
  if [ "$tries" -gt 300 ]; then
    echo "xvfb_run.sh: Xvfb did not start within 30 s" >&2
    kill "$xvfb" 2>/dev/null
    rm -rf "$dir"
    exit 1
  fi
  sleep 0.1
done
DISPLAY=":$(head -n 1 "$dir/display")" "$@"
status=$?
kill "$xvfb" 2>/dev/null
wait "$xvfb" 2>/dev/null
rm -rf "$dir"
exit $status

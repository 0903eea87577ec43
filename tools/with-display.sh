#!/bin/sh
# Runs a command with an X display: $DISPLAY when set, else a private Xvfb started for it
# (it picks a free display number itself) and stopped afterwards. Exits with the command's
# status.
if [ -n "$DISPLAY" ]; then
    exec "$@"
fi
dir=$(mktemp -d) || exit 1
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" 2>"$dir/log" &
server=$!
# Xvfb writes the display number when it accepts connections; 20 s at most.
tries=0
while [ ! -s "$dir/display" ] && kill -0 "$server" 2>/dev/null && [ "$tries" -lt 200 ]; do
    sleep 0.1
    tries=$((tries + 1))
done
if [ ! -s "$dir/display" ]; then
    echo "with-display.sh: Xvfb did not start:" >&2
    cat "$dir/log" >&2
    kill "$server" 2>/dev/null
    rm -rf "$dir"
    exit 1
fi
DISPLAY=":$(cat "$dir/display")" "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
rm -rf "$dir"
exit "$status"

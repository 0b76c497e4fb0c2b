#!/usr/bin/env bash
# CTest fixture: one Xvfb for the whole test run (parallel `xvfb-run -a` calls race for display
# numbers). `xvfb.sh start DIR` starts it on a free display (Xvfb picks it: -displayfd) and writes
# DIR/xvfb.display and DIR/xvfb.pid; `xvfb.sh stop DIR` stops it. -noreset: by default an X server
# resets when its last client leaves, and a meshlabserver connecting during that reset fails
# ("could not connect to display"; seen once with two tests in parallel, in a CI run on 1acd049).
set -euo pipefail
cmd="$1"; dir="$2"
mkdir -p "$dir"

# Stops the server and waits until it is gone: an exiting Xvfb removes its socket file, which
# would delete the socket of a server started right after it on the same display number.
stop_server() {
  local pid
  pid="$(cat "$dir/xvfb.pid" 2>/dev/null || true)"
  [ -n "$pid" ] || return 0
  # a pid file left by an aborted run may name a process that has since been reused: only an Xvfb
  [ "$(cat "/proc/$pid/comm" 2>/dev/null || true)" = "Xvfb" ] || return 0
  kill "$pid" 2>/dev/null || return 0
  for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.05; done
  kill -9 "$pid" 2>/dev/null || true
}

case "$cmd" in
  start)
    stop_server
    rm -f "$dir/xvfb.display" "$dir/xvfb.pid" "$dir/xvfb.fd"
    # setsid: the server outlives this script (CTest waits only for the script)
    setsid Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$dir/xvfb.fd" >"$dir/xvfb.log" 2>&1 < /dev/null &
    echo $! > "$dir/xvfb.pid"
    # up to 30 s (a loaded machine); the loop ends as soon as the display is known
    for _ in $(seq 1 300); do
      if [ -s "$dir/xvfb.fd" ]; then echo ":$(tr -d '[:space:]' < "$dir/xvfb.fd")" > "$dir/xvfb.display"; break; fi
      sleep 0.1
    done
    [ -s "$dir/xvfb.display" ] || { echo "Xvfb did not start:"; cat "$dir/xvfb.log"; exit 1; }
    echo "Xvfb running on $(cat "$dir/xvfb.display")"
    ;;
  stop)
    stop_server
    rm -f "$dir/xvfb.display" "$dir/xvfb.pid" "$dir/xvfb.fd"
    ;;
  *) echo "usage: $0 start|stop DIR" >&2; exit 2 ;;
esac

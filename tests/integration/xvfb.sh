#!/usr/bin/env bash
# CTest fixture: one Xvfb for the whole test run (parallel `xvfb-run -a` calls race for display
# numbers). `xvfb.sh start DIR` starts it on a free display (Xvfb picks it: -displayfd) and writes
# DIR/xvfb.display and DIR/xvfb.pid; `xvfb.sh stop DIR` stops it.
set -euo pipefail
cmd="$1"; dir="$2"
mkdir -p "$dir"
case "$cmd" in
  start)
    if [ -f "$dir/xvfb.pid" ] && kill -0 "$(cat "$dir/xvfb.pid")" 2>/dev/null; then
      kill "$(cat "$dir/xvfb.pid")" 2>/dev/null || true
    fi
    rm -f "$dir/xvfb.display" "$dir/xvfb.pid" "$dir/xvfb.fd"
    # setsid: the server outlives this script (CTest waits only for the script)
    setsid Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/xvfb.fd" >"$dir/xvfb.log" 2>&1 < /dev/null &
    echo $! > "$dir/xvfb.pid"
    for _ in $(seq 1 100); do
      if [ -s "$dir/xvfb.fd" ]; then echo ":$(tr -d '[:space:]' < "$dir/xvfb.fd")" > "$dir/xvfb.display"; break; fi
      sleep 0.1
    done
    [ -s "$dir/xvfb.display" ] || { echo "Xvfb did not start:"; cat "$dir/xvfb.log"; exit 1; }
    echo "Xvfb running on $(cat "$dir/xvfb.display")"
    ;;
  stop)
    if [ -f "$dir/xvfb.pid" ]; then kill "$(cat "$dir/xvfb.pid")" 2>/dev/null || true; fi
    rm -f "$dir/xvfb.display" "$dir/xvfb.pid" "$dir/xvfb.fd"
    ;;
  *) echo "usage: $0 start|stop DIR" >&2; exit 2 ;;
esac

#!/usr/bin/env bash
# How far the viewer's camera turns for ← held 2 s and tapped for 50 ms, at each size and view,
# however long its frames take (issue 48, docs/viewer.md "Controls"): the documented rate is
# 60° a second, so 120° and 3°. The viewer runs under Xvfb; the key's press and release are
# sent to its window through Xlib (python3's ctypes), 2 s or 50 ms apart by this machine's
# clock; `C` then prints the camera, whose yaw about the look-at point is the turn. The panel
# report gives the frame time and the longest the viewer went without reading its input.
# Prints the machine and its load first.
#
#   scripts/measure-held-keys.sh
#   SIZES=1920x1080 VIEWS=light-count scripts/measure-held-keys.sh
set -euo pipefail
cd "$(dirname "$0")/.."
ML=${ML:-$(scripts/lib/bench.py --binary)}
scripts/lib/bench.py --machine
sizes=${SIZES:-320x180 1280x720 1920x1080}
views=${VIEWS:-final light-count}
out=out/held-keys
mkdir -p "$out"
ml=$(realpath "$ML")

# Sends ← down, waits SECONDS, sends it up, to the viewer's window.
cat >"$out/send-key.py" <<'PY'
import ctypes, sys, time
x = ctypes.cdll.LoadLibrary("libX11.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
x.XOpenDisplay.argtypes = [ctypes.c_char_p]
x.XDefaultRootWindow.restype = ctypes.c_ulong
x.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
x.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                         ctypes.POINTER(ctypes.c_ulong), ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                         ctypes.POINTER(ctypes.c_uint)]
x.XGetGeometry.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong)] + \
    [ctypes.POINTER(ctypes.c_int)] * 2 + [ctypes.POINTER(ctypes.c_uint)] * 4
x.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
x.XKeysymToKeycode.restype = ctypes.c_ubyte
x.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long, ctypes.c_void_p]
x.XFlush.argtypes = [ctypes.c_void_p]


class KeyEvent(ctypes.Structure):  # XKeyEvent, padded to XEvent's size
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("window", ctypes.c_ulong), ("root", ctypes.c_ulong),
                ("subwindow", ctypes.c_ulong), ("time", ctypes.c_ulong), ("x", ctypes.c_int), ("y", ctypes.c_int),
                ("x_root", ctypes.c_int), ("y_root", ctypes.c_int), ("state", ctypes.c_uint),
                ("keycode", ctypes.c_uint), ("same_screen", ctypes.c_int), ("pad", ctypes.c_long * 16)]


display = x.XOpenDisplay(None)
root = x.XDefaultRootWindow(display)
parent, children, count = ctypes.c_ulong(), ctypes.POINTER(ctypes.c_ulong)(), ctypes.c_uint()
x.XQueryTree(display, root, ctypes.byref(ctypes.c_ulong()), ctypes.byref(parent), ctypes.byref(children),
             ctypes.byref(count))
# GLFW's windows: the viewer's, and a 1x1 helper of its own; the largest is the viewer's.
def area(window):
    width, height, unused = ctypes.c_uint(), ctypes.c_uint(), ctypes.c_uint()
    x.XGetGeometry(display, window, ctypes.byref(ctypes.c_ulong()), ctypes.byref(ctypes.c_int()),
                   ctypes.byref(ctypes.c_int()), ctypes.byref(width), ctypes.byref(height), ctypes.byref(unused),
                   ctypes.byref(ctypes.c_uint()))
    return width.value * height.value


window = max((children[i] for i in range(count.value)), key=area)
left = x.XKeysymToKeycode(display, 0xFF51)  # XK_Left
KEY_PRESS, KEY_RELEASE = 2, 3
KEY_PRESS_MASK, KEY_RELEASE_MASK = 1, 2


def send(kind, mask):
    event = KeyEvent(type=kind, display=display, window=window, root=root, same_screen=1, keycode=left)
    x.XSendEvent(display, window, 1, mask, ctypes.byref(event))
    x.XFlush(display)


send(KEY_PRESS, KEY_PRESS_MASK)
pressed = time.monotonic()
time.sleep(float(sys.argv[1]))
released = time.monotonic()
send(KEY_RELEASE, KEY_RELEASE_MASK)
print(f"{released - pressed:.3f}")  # how long the key was down, by this clock
PY

# held_s: the time between the press and the release sent, by the sender's clock (its sleep
# may overrun under load); expected_deg: 60° a second of it; turned_deg: the camera's turn.
printf '%-10s %-12s %8s %13s %11s %10s %15s\n' size view held_s expected_deg turned_deg frame_ms longest_gap_ms
for size in $sizes; do
  for view in $views; do
    for seconds in 2.0 0.05; do
      rm -f "$out"/{ready.txt,report.txt,go,sent,camera.txt,held.txt}
      cat >"$out/script.txt" <<EOF
pause
view $view
frames 3
report-panel ready.txt
wait-for go
wait-for sent
frames 3
report-panel report.txt
key c
frames 1
quit
EOF
      (cd "$out" && xvfb-run -a -s '-screen 0 2000x1200x24' bash -c '
        "$0" view --size "$1" --script script.txt --eye 0,2,10 --look-at 0,0,0 --up 0,1,0 >camera.txt 2>view.log &
        while [ ! -e ready.txt ]; do sleep 0.1; done
        touch go
        python3 send-key.py "$2" >held.txt && touch sent
        wait' "$ml" "$size" "$seconds")
      turned=$(python3 -c 'import math, re, sys
x, y, z = map(float, re.search(r"--eye (\S+)", open(sys.argv[1]).read()).group(1).split(","))
print(f"{-math.degrees(math.atan2(x, z)):.1f}")' "$out/camera.txt")
      read -r _ frame_ms gap_ms < <(grep '^input ' "$out/report.txt")
      held=$(cat "$out/held.txt")
      expected=$(python3 -c "print(f'{60 * $held:.1f}')")
      printf '%-10s %-12s %8s %13s %11s %10s %15s\n' "$size" "$view" "$held" "$expected" "$turned" "$frame_ms" \
        "$gap_ms"
    done
  done
done

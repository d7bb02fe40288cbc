# Sourced by frame_times.sh and playback_frame_times.sh (which define run() and $tmp).
# The empty frame runs at one of two speeds (about 0.8 or 1.1 ms at 1280x800), the same for
# a whole run: it is timed KINEMA_EMPTY_RUNS times (3) and each ratio is given against all.
# (In the slow runs llvmpipe's two raster threads share its whole-window clear and the
# process uses 0.4-0.5 ms more CPU a frame; in the fast runs one thread does nearly all of it.)

empties() {  # size run-arguments...: the empty frame's runs, into $tmp/empty1.txt ...
  local k
  for k in $(seq "${KINEMA_EMPTY_RUNS:-3}"); do run "$@" --empty-frame | tee "$tmp/empty$k.txt"; done
}

ratio() {  # frames.txt label empty.txt...: the medians' ratios to each empty frame's
  python3 - "$@" <<'PY'
import re, sys
def median(path):
    m = re.findall(r"median ([0-9.]+) ms", open(path).read())
    return float(m[-1]) if m else float("nan")
a, label, empties = median(sys.argv[1]), sys.argv[2], [median(p) for p in sys.argv[3:]]
lo, hi = a / max(empties), a / min(empties)
shown = " / ".join(f"{b:.2f}" for b in empties)
print(f"{label}: {a:.2f} / ({shown}) ms = " + (f"{lo:.2f}x" if f"{lo:.2f}" == f"{hi:.2f}" else f"{lo:.2f}-{hi:.2f}x"))
PY
}

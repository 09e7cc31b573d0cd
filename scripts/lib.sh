# Shared by the scripts: sourced, not run.

# ninja_progress WHAT: reads a build's output and turns Ninja's "[n/N] …" lines into one line per
# tenth on stderr ("azeltrack: building WHAT: 40% (…)"); anything else (warnings, errors) shows
# as is.
ninja_progress() {
  awk -v what="$1" '
    match($0, /^\[[0-9]+\/[0-9]+\]/) {
      split(substr($0, 2, RLENGTH - 2), nn, "/")
      tenth = int(nn[1] * 10 / nn[2])
      if (nn[1] > 0 && tenth != shown) { printf "azeltrack: building %s: %d%% (%d of %d steps)\n", what, tenth * 10, nn[1], nn[2] > "/dev/stderr"; shown = tenth }
      next
    }
    /^ninja: no work to do/ { next }
    { print > "/dev/stderr" }
    BEGIN { shown = -1 }'
}

# Shared by the scripts: sourced, not run.

# The caches live outside the clone, so that a fresh clone (CI's) on the same machine reuses them
# (docs/building.md, "The caches"): ccache's objects, clang-tidy's results
# (tests/lint/tidy_cache.py) and the upgrade test's Debian root. CCACHE_BASEDIR makes paths under
# the clone relative, so clones at other paths share the objects; a ccache.conf of the user's own
# still applies to the rest.
azt_cache=${AZT_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/azeltrack}
export CCACHE_DIR=${CCACHE_DIR:-$azt_cache/ccache}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-8G}
# The build folder is not part of an object's key (hash_dir off), so the package build
# (build/deb/src-ARCH/obj-…) takes the dev build's objects (build/): the same flags, the same
# paths relative to base_dir. The price: an object's debug information may name the other
# build's folder as its compilation directory (gdb: `directory` to the clone).
export CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
# ccache keys on the locale variables that are set (LANG, LC_ALL, LC_CTYPE, LC_MESSAGES: they
# change the compiler's messages), and debhelper runs the package build with LC_ALL=C.UTF-8: every
# build gets the same locale, so that the dev build's objects are the package's and a run's keys
# do not depend on the caller's locale.
export LANG=C.UTF-8 LC_ALL=C.UTF-8
unset LC_CTYPE LC_MESSAGES
export AZT_TIDY_CACHE=${AZT_TIDY_CACHE:-$azt_cache/clang-tidy}

# line_awk ARGS…: awk that reads and writes a line at a time. Debian's default awk (mawk) reads
# its input in blocks and buffers its output, so progress would arrive in bursts; its
# "-W interactive" reads lines and writes unbuffered (gawk and busybox awk read lines already).
line_awk() {
  if awk -W version 2>/dev/null | grep -q '^mawk'; then awk -W interactive "$@"; else awk "$@"; fi
}

# ninja_progress WHAT: reads a build's output and turns Ninja's "[n/N] …" lines into one line per
# tenth on stderr ("azeltrack: building WHAT: 40% (…)"); anything else (warnings, errors) shows
# as is.
ninja_progress() {
  line_awk -v what="$1" '
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

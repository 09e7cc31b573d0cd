# Shared by the CLI test scripts (sourced): counters and the usage-error check.
# Expects $bin (the azeltrack binary) and $tmp (a scratch directory) to be set.

passed=0
failed=0

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }

# expect_usage_error DESCRIPTION ARGS...: exit code 2, exactly one line on stderr, nothing on stdout.
expect_usage_error() {
  local what=$1; shift
  "$bin" "$@" </dev/null >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  local lines; lines=$(wc -l <"$tmp/err")
  if [ $rc -ne 2 ] || [ "$lines" -ne 1 ] || [ -s "$tmp/out" ]; then
    bad "$what: rc=$rc, stderr lines=$lines: $(cat "$tmp/err")"
  else
    ok
  fi
}

# finish: the closing line, and the exit status.
finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}

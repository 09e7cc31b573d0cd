#!/usr/bin/env bash
# Pointing calibration in simulation (docs/calibration.md): the mount's errors of
# examples/calibrate.toml (every term up to 1°, 0.1 dB of noise per reading) recovered by the
# daemon's calibration session from scans across the sky, with 16-bit encoders and down to the
# quantisation floor of 12-bit ones; a single Sun cross scan finds the az/el offsets; refusals
# name their reason.
# Usage: calibrate_test.sh path/to/azeltrack
set -uo pipefail
bin=${1:?usage: calibrate_test.sh AZELTRACK}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=lib.sh
source "$(dirname "$0")/lib.sh"

cal=(simulate --config "$root/examples/calibrate.toml")

# The whole scenario, the daemon's calibration session on 16-bit encoders: every fitted term
# within three of its standard errors of the injected one (and the encoders' half count, which
# the fit takes into IA and IE: a count reads the bottom of its step), none held, and the beam's
# true error over the sky from over 0.3° rms to at most 0.02° rms.
if "$bin" "${cal[@]}" --scenario calibrate --from 2025-06-01T00:00:00Z --hours 36 --json >"$tmp/cal" 2>"$tmp/err"; then
  if "$py" - "$tmp/cal" <<'PY'; then ok; else bad "calibrate: $(head -c 600 "$tmp/cal")"; fi
import json, sys
j = json.load(open(sys.argv[1]))
half_count = 360 / 2**16 / 2
worst = max(abs(j['fitted'][k] - j['injected'][k]) for k in j['injected'])
print(f"calibrate: {len(j['scans'])} sources, {j['log_rows']} log rows, largest term error "
      f"{worst:.4f}°, beam error {j['before']['residual_rms_deg']:.3f}° → "
      f"{j['after']['residual_rms_deg']:.4f}° rms (max {j['after']['residual_max_deg']:.4f}°), "
      f"with the encoders {j['after_with_encoders']['residual_rms_deg']:.4f}° (floor "
      f"{j['quantisation_floor_deg']:.4f}°), {j['cpu_s']:.1f} s of CPU")
for k in j['injected']:
    assert abs(j['fitted'][k] - j['injected'][k]) <= 3 * j['std_errors'][k] + half_count, k
assert worst <= 0.02, worst
assert abs(j['largest_term_error_deg'] - worst) < 1e-12
assert j['held'] == {}, j['held']
assert j['before']['residual_rms_deg'] > 0.3
assert j['after']['residual_rms_deg'] <= 0.02
assert j['after_with_encoders']['residual_rms_deg'] <= 0.02
assert j['faults'] == []
assert len(j['scans']) >= 30 and j['log_rows'] >= 60
# Each scan alone is as good as its source is bright: within 0.05° even for Taurus A at 1 dB.
assert all(abs(s['xel_offset_deg'] - s['true_xel_offset_deg']) < 0.05 and
           abs(s['el_offset_deg'] - s['true_el_offset_deg']) < 0.05
           for s in j['scans'] if 'refused' not in s)
PY
else
  bad "calibrate: exit $? $(cat "$tmp/err")"
fi

# 12-bit encoders (0.088° a count): the shaft may stand anywhere in the count its reading names,
# q/√12 rms per axis, √(q²·cos²E + q²)/√12 on the sky: 0.031° rms over the grid. The session
# reaches that floor (within 5 %); the fitted IA and IE take in the half count. The Sun every
# 60 minutes while it is up, start to start (after the scan running then).
sed 's/^encoder_bits = 16/encoder_bits = 12/' "$root/examples/calibrate.toml" >"$tmp/bits12.toml"
if "$bin" simulate --config "$tmp/bits12.toml" --scenario calibrate --from 2025-06-01T00:00:00Z \
  --hours 18 --sun-every-min 60 --json >"$tmp/cal12" 2>"$tmp/err"; then
  if "$py" - "$tmp/cal12" <<'PY'; then ok; else bad "calibrate 12 bits: $(head -c 600 "$tmp/cal12")"; fi
import json, math, sys
j = json.load(open(sys.argv[1]))
q = 360 / 2**12
grid = [10 + 5 * i for i in range(15)]
floor = math.sqrt(sum(q * q * (math.cos(math.radians(e)) ** 2 + 1) / 12 for e in grid) / len(grid))
true_rms = j['after_with_encoders']['residual_rms_deg']
print(f"calibrate, 12 bits: {len(j['scans'])} sources, beam's true error {true_rms:.4f}° rms, "
      f"quantisation floor {j['quantisation_floor_deg']:.4f}°, {j['cpu_s']:.1f} s of CPU")
assert abs(j['quantisation_floor_deg'] - floor) < 1e-9
assert true_rms <= 1.05 * floor, (true_rms, floor)
for k in ('ia_deg', 'ie_deg'):
    assert abs(j['fitted'][k] - j['injected'][k] + q / 2) < 0.01, k
sun = [s['time'] for s in j['scans'] if s['source'] == 'sun']
assert len(sun) >= 5, sun
assert j['plan']['sun_every_s'] == 3600
PY
else
  bad "calibrate 12 bits: exit $? $(cat "$tmp/err")"
fi
expect_usage_error "--sun-every-min below 0" "${cal[@]}" --scenario calibrate --sun-every-min -5

# One Sun cross scan with only the encoders' zeros wrong finds them within 0.01°.
sed -E 's/^(collimation_deg|nonperp_deg|az_tilt_deg|el_sag_deg) = [-0-9.]+/\1 = 0.0/' \
  "$root/examples/calibrate.toml" >"$tmp/offsets.toml"
for from in 2025-03-14T15:00:00Z 2025-06-01T16:00:00Z; do
  if "$bin" simulate --config "$tmp/offsets.toml" --scenario scan --source sun --from "$from" --json >"$tmp/scan" 2>"$tmp/err"; then
    "$py" - "$tmp/scan" <<'PY' && ok || bad "sun scan at $from: $(cat "$tmp/scan")"
import json, sys
j = json.load(open(sys.argv[1]))
f = j['found']
print(f"sun scan: az {f['az_offset_deg']:.4f}° el {f['el_offset_deg']:.4f}° (injected 0.8, -0.6)")
assert abs(f['az_offset_deg'] - 0.8) <= 0.01 and abs(f['el_offset_deg'] + 0.6) <= 0.01
assert abs(j['true']['az_offset_deg'] - 0.8) < 1e-9
PY
  else
    bad "sun scan at $from: exit $? $(cat "$tmp/err")"
  fi
done

# Refusals: an unknown source, the Sun at night, bad receiver and mount settings.
expect_usage_error "scan of an unknown source" "${cal[@]}" --scenario scan --source vega --from 2025-06-01T16:00:00Z
"$bin" "${cal[@]}" --scenario scan --source sun --from 2025-06-01T04:00:00Z --json >"$tmp/night" 2>/dev/null
rc=$?
"$py" -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if 'refused' in j['scan'] else 1)" "$tmp/night" && [ $rc -eq 1 ] \
  && ok || bad "a scan of the Sun at night was not refused (rc $rc): $(cat "$tmp/night")"
sed 's/^beamwidth_deg = 1.6 /beamwidth_deg = 0.0 /' "$root/examples/calibrate.toml" >"$tmp/bw.toml"
expect_usage_error "receiver beamwidth 0" simulate --config "$tmp/bw.toml" --scenario scan --source sun
sed 's/^az_tilt_deg = 0.5 /az_tilt_deg = 12.0 /' "$root/examples/calibrate.toml" >"$tmp/tilt.toml"
expect_usage_error "mount error beyond 10°" simulate --config "$tmp/tilt.toml" --scenario scan --source sun
sed 's/^ia_deg = 0.0/ia_deg = "x"/' "$root/examples/calibrate.toml" >"$tmp/ia.toml"
expect_usage_error "pointing term not a number" simulate --config "$tmp/ia.toml" --scenario scan --source sun

finish

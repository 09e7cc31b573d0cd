#!/usr/bin/env bash
# Sun noise, Moon noise and drift scans in simulation (docs/calibration.md): on the 10 m dish of
# examples/calibrate.toml (every mount term up to 1° wrong, 0.1 dB of noise per reading) the
# measured Y-factor is within 0.2 dB of the simulated receiver's own truth, the value expected from
# the source's flux and the dish is the simulated one times the main-beam share, and a drift scan
# finds the simulated beamwidth within 5 %. Refusals name their reason. A few seconds of CPU.
# Usage: noise_test.sh path/to/azeltrack
set -uo pipefail
bin=${1:?usage: noise_test.sh AZELTRACK}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=lib.sh
source "$(dirname "$0")/lib.sh"

cal=(simulate --config "$root/examples/calibrate.toml")

# run NAME ARGS...: the scenario's JSON in $tmp/NAME; the exit status kept in $tmp/NAME.rc.
run() {
  local name=$1; shift
  "$bin" "${cal[@]}" "$@" --json >"$tmp/$name" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.rc"
}

# The Sun at 61° (the Moon 70° away, low in the east), and the Moon near its transit at night.
run sun --scenario sun-noise --from 2025-06-01T16:00:00Z
run moon --scenario moon-noise --from 2025-06-06T01:00:00Z
for name in sun moon; do
  if [ "$(cat "$tmp/$name.rc")" = 0 ] && "$py" - "$tmp/$name" <<'PY'; then ok; else bad "$name-noise: $(head -c 800 "$tmp/$name") $(cat "$tmp/$name.err")"; fi
import json, math, sys
j = json.load(open(sys.argv[1]))
x = j['expected']
print(f"{j['scenario']}: Y {j['y_factor_db']:.3f} ± {j['std_error_db']:.3f} dB, truth {j['truth_db']:.3f} dB "
      f"({j['difference_db']:+.3f}); expected from {x['flux_sfu']:.2f} SFU and the dish {x['y_db']:.3f} dB; "
      f"G/T {x['g_over_t_db']:.2f} dB/K; {j['simulated_s']:.0f} s simulated, {j['cpu_s']:.2f} s of CPU")
assert abs(j['y_factor_db'] - j['truth_db']) <= 0.2
assert 0 < j['std_error_db'] < 0.05
assert j['pairs'] == 4 and len(j['pair_y_db']) == 4 and j['missed'] == 0
assert j['faults'] == []
assert 'peak' in j
# The core's formula on the simulated Sun's flux gives the simulated rise times the share of a
# real dish's beam in its main lobe (the simulated beam keeps all of it): T_A = share·T_truth.
tsys = 50.0
truth_k = tsys * (10 ** (j['truth_db'] / 10) - 1)
assert abs(x['antenna_k'] - x['main_beam_share'] * truth_k) <= 1e-6 * truth_k, (x, truth_k)
# And the figure of merit read back from the measured Y gives the system temperature back.
assert abs(x['implied_tsys_k'] / x['main_beam_share'] - tsys) < 0.05 * tsys
PY
done

# A drift of the Sun through the held beam, near its transit (its path along the azimuth), and
# of Cygnus A: the beamwidth within 5 % of the simulated 1.6°, the offset along the path within
# 0.02° of the mount's true error there.
run drift_sun --scenario drift --from 2025-06-01T16:55:00Z
run drift_cyg --scenario drift --source cyga --from 2025-06-01T03:00:00Z
for name in drift_sun drift_cyg; do
  if [ "$(cat "$tmp/$name.rc")" = 0 ] && "$py" - "$tmp/$name" <<'PY'; then ok; else bad "$name: $(head -c 800 "$tmp/$name") $(cat "$tmp/$name.err")"; fi
import json, sys
j = json.load(open(sys.argv[1]))
print(f"drift of {j['source']}: beamwidth {j['beamwidth_deg']:.4f}° (simulated {j['truth_beamwidth_deg']}°, "
      f"{j['beamwidth_error_pct']:+.2f} %), along the path {j['along_offset_deg']:+.4f}° "
      f"(true {j['true_along_offset_deg']:+.4f}°), at {j['rate_deg_s'] * 3600:.2f}°/h; "
      f"{j['simulated_s']:.0f} s simulated, {j['cpu_s']:.2f} s of CPU")
assert abs(j['beamwidth_error_pct']) <= 5.0
assert abs(j['along_offset_deg'] - j['true_along_offset_deg']) <= 0.02
assert j['faults'] == []
PY
done

# Refusals: the Sun at night, an unknown source, a bad scenario name.
run night --scenario sun-noise --from 2025-06-01T04:00:00Z
"$py" -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if 'below' in j['refused'] else 1)" "$tmp/night" \
  && [ "$(cat "$tmp/night.rc")" = 1 ] && ok || bad "sun-noise at night was not refused: $(cat "$tmp/night")"
expect_usage_error "drift of an unknown source" "${cal[@]}" --scenario drift --source vega --from 2025-06-01T16:55:00Z
expect_usage_error "an unknown scenario" "${cal[@]}" --scenario star-noise

finish

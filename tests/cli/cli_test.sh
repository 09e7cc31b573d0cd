#!/usr/bin/env bash
# The command line as users and scripts meet it: JSON fields, exit codes, one-line errors.
# Usage: cli_test.sh path/to/azeltrack
set -uo pipefail
bin=${1:?usage: cli_test.sh AZELTRACK}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=lib.sh
source "$(dirname "$0")/lib.sh"

# json_check DESCRIPTION PYTHON_EXPR ARGS...: runs azeltrack, evaluates the expression on `j`.
json_check() {
  local what=$1 expr=$2; shift 2
  if ! "$bin" "$@" >"$tmp/out" 2>"$tmp/err"; then
    bad "$what: exit $? $(cat "$tmp/err")"; return
  fi
  if "$py" -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if ($expr) else 1)" "$tmp/out"; then
    ok
  else
    bad "$what: $expr is false for $(head -c 400 "$tmp/out")"
  fi
}

at=(--at 2025-03-14T06:00:00Z)
station=(--lat 46.189 --lon -79.393 --alt 300)

"$bin" --help >"$tmp/out" 2>&1 && grep -q sky "$tmp/out" && grep -q locator "$tmp/out" && grep -q watch "$tmp/out" && ok || bad "--help"
"$bin" sky --help >"$tmp/out" 2>&1 && grep -q -- --freq-mhz "$tmp/out" && ok || bad "sky --help"

json_check "sky moon fields" \
  "all(k in j for k in ['az_deg','el_deg','el_geometric_deg','ra_deg','dec_deg','distance_km','range_rate_km_s']) and 'echo_doppler_hz' not in j" \
  sky moon "${at[@]}" "${station[@]}" --json
json_check "moon az/el near the oracle (swetest 192.378 / 45.454)" \
  "abs(j['az_deg']-192.378)<0.01 and abs(j['el_geometric_deg']-45.454)<0.01 and j['el_deg']>j['el_geometric_deg']" \
  sky moon "${at[@]}" "${station[@]}" --json --dut1 0.203387
json_check "echo doppler at --freq-mhz is -2 f rdot / c" \
  "abs(j['echo_doppler_hz'] + 2*10368e6*j['range_rate_km_s']/299792.458) < 1e-6 and len(j['bands'])>=14" \
  sky moon "${at[@]}" "${station[@]}" --freq-mhz 10368 --json
json_check "dx echo doppler" "'dx_echo_doppler_hz' in j and j['dx']['grid']=='JO20'" \
  sky moon "${at[@]}" --grid FN06HE --freq-mhz 1296 --dx-grid JO20 --json
json_check "erfa backend selectable" "j['ephemeris']=='erfa'" sky sun "${at[@]}" "${station[@]}" --ephemeris erfa --json
json_check "radio source has no distance" "j['distance_km'] is None and j['target']=='Cassiopeia A'" \
  sky casa "${at[@]}" "${station[@]}" --json
json_check "radec target" "abs(j['ra_deg']-83.8)<1 and j['range_rate_km_s'] is None" \
  sky radec:83.633,22.0145 "${at[@]}" "${station[@]}" --json
json_check "refraction none" "j['el_deg']==j['el_geometric_deg']" \
  sky moon "${at[@]}" "${station[@]}" --refraction none --json
json_check "catalogue list" "any(s['key']=='casa' for s in j) and any('leo' in s['aliases'] for s in j)" sky --list --json
json_check "locator centre" "abs(j['lat_deg']-46.1875)<1e-9 and abs(j['lon_deg']+79.375)<1e-9" locator FN06HE --json
json_check "locator from position" "j['locator'].upper()=='FN06HE'" locator --lat 46.189 --lon -79.393 --json

# DUT1 beyond ±0.9 s is accepted with a warning on stderr.
if "$bin" sky moon "${at[@]}" "${station[@]}" --dut1 2.5 --json >"$tmp/out" 2>"$tmp/err" && grep -qi warn "$tmp/err"; then ok; else bad "--dut1 2.5 should warn and succeed"; fi

expect_usage_error "latitude out of range" sky moon "${at[@]}" --lat 100 --lon 0
expect_usage_error "nan latitude" sky moon "${at[@]}" --lat nan --lon 0
expect_usage_error "bad locator" sky moon "${at[@]}" --grid ZZ99
expect_usage_error "grid and lat" sky moon "${at[@]}" --grid FN06 --lat 1 --lon 1
expect_usage_error "no station" sky moon "${at[@]}"
expect_usage_error "bad instant" sky moon --at yesterday "${station[@]}"
expect_usage_error "instant without zone" sky moon --at 2025-03-14T06:00:00 "${station[@]}"
expect_usage_error "unknown target" sky jupiter "${at[@]}" "${station[@]}"
expect_usage_error "dut1 too large" sky moon "${at[@]}" "${station[@]}" --dut1 11
expect_usage_error "bad frequency" sky moon "${at[@]}" "${station[@]}" --freq-mhz -5
expect_usage_error "unknown ephemeris" sky moon "${at[@]}" "${station[@]}" --ephemeris jpl
expect_usage_error "unknown option" sky moon "${at[@]}" "${station[@]}" --frobnicate
expect_usage_error "no subcommand"
expect_usage_error "bad locator (decode)" locator FN0
expect_usage_error "bad humidity" sky moon "${at[@]}" "${station[@]}" --humidity 3

# watch: one frame for a fixed instant, from the example configuration.
if "$bin" watch --config "$root/examples/station.toml" --count 1 "${at[@]}" >"$tmp/out" 2>"$tmp/err" \
   && grep -q '^Moon ' "$tmp/out" && grep -q 'Echo' "$tmp/out" && grep -q 'Cassiopeia A' "$tmp/out"; then
  ok
else
  bad "watch frame: $(cat "$tmp/out" "$tmp/err")"
fi
printf '[station]\ngrid = "FN06"\n[sky]\nbandd = "144"\n' >"$tmp/typo.toml"
expect_usage_error "config unknown key" watch --config "$tmp/typo.toml" --count 1
printf '[station]\nlat_deg = 46\n' >"$tmp/half.toml"
expect_usage_error "config lat without lon" watch --config "$tmp/half.toml" --count 1
expect_usage_error "config missing" watch --config "$tmp/none.toml" --count 1

# simulate: the controller on the simulated antenna, in virtual time.
sim=(simulate --config "$root/examples/sim.toml")
json_check "simulate slew" \
  "j['slew_time_s'] is not None and j['slew_time_s'] <= 1.1*j['slew_min_time_s'] + 1 and j['faults'] == [] and j['overshoot_deg'] >= 0" \
  "${sim[@]}" --scenario slew --to-az 300 --to-el 30 --json
json_check "simulate moon" \
  "all(k in j for k in ['rms_error_deg','max_error_deg','slew_time_s','slew_min_time_s','overshoot_deg','faults']) and set(j['motor_starts_per_hour']) == {'az','el'} and j['max_error_deg'] < 0.3" \
  "${sim[@]}" --scenario moon --from 2025-03-14T02:00:00Z --hours 0.5 --json
# [sim.az] brake (docs/control.md): released before the brake lifts, the motor pulls against it.
sed 's/^start_deg = 180.0$/start_deg = 180.0\nbrake = true\nbrake_lift_s = 1.2\nbrake_release_s = 0.5/' \
  "$root/examples/sim.toml" >"$tmp/brake.toml"
json_check "simulate slew with a brake released too soon" \
  "0.6 < j['brake_pulled_against_s']['az'] < 0.8 and j['brake_pulled_against_s']['el'] == 0 and j['faults'] == []" \
  simulate --config "$tmp/brake.toml" --scenario slew --to-az 300 --to-el 30 --json
json_check "simulate moon: no pol figures without [mount.pol]" \
  "'pol_max_error_deg' not in j and 'pol' not in j" \
  "${sim[@]}" --scenario moon --from 2025-03-14T02:00:00Z --hours 0.1 --json
# The polarisation axis (docs/eme.md): split mode on 60 s periods, FN06 to JO22.
json_check "simulate moon with a pol axis: split within 1 deg after settling" \
  "j['pol']['mode'] == 'split' and j['pol_max_error_deg'] < 1.0 and 0 < j['pol_rms_error_deg'] < 0.5 and j['pol']['settle_s'] == 23.0 and j['pol']['counted_s'] > 600 and j['faults'] == []" \
  simulate --config "$root/examples/pol.toml" --scenario moon --from 2025-03-14T00:00:00Z --hours 0.5 --ptt-period-s 60 --json
# A fixed-elevation array (docs/eme.md): azimuth within window + 2 LSB, the elevation not tracked.
json_check "simulate moon on a fixed-elevation array: azimuth within window + 2 LSB" \
  "j['el'] == {'fixed_deg': 12.0} and j['az']['max_error_deg'] <= 0.5 + 2 * 360 / 4096 and j['motor_starts_per_hour']['el'] == 0 and j['acquired_s'] is not None and j['faults'] == []" \
  simulate --config "$root/examples/fixed_el.toml" --scenario moon --from 2025-03-14T00:00:00Z --hours 0.5 --json
# An elevation actuator read by its feedback pot (docs/hardware.md, "Linear actuators"): nothing to
# home; the elevation within the window + a step (the stroke's coarsest ADC count, 0.5715 mm at
# 0.3086 deg/mm) + half a count of the code's rounding.
json_check "simulate moon on an actuator dish read by its pot" \
  "j['acquired_s'] is not None and j['el']['max_error_deg'] <= 0.2 + 1.5 * 0.5715 * 0.3086 and j['el']['rms_error_deg'] < 0.2 and j['el']['starts'] > 0 and j['faults'] == []" \
  simulate --config "$root/examples/actuator_dish_pot.toml" --scenario moon --from 2025-03-14T04:00:00Z --hours 0.5 --json
json_check "moon-windows in a fixed array's beam" \
  "j['el_band_deg'] == [2.0, 22.0] and len(j['windows']) > 0 and all(2.0 <= w['el_deg'] <= 22.0 for w in j['windows'])" \
  moon-windows --grid FN06HE --dx-grid JO22 --from 2025-03-01T00:00:00Z --days 3 --fixed-el 12 --beam-width 20 --ephemeris erfa --json
expect_usage_error "moon-windows bad beam width" moon-windows --grid FN06HE --dx-grid JO22 --fixed-el 12 --beam-width 0
expect_usage_error "simulate bad PTT period" simulate --config "$root/examples/pol.toml" --scenario moon --ptt-period-s -1
expect_usage_error "simulate bad scenario" "${sim[@]}" --scenario mars
expect_usage_error "simulate slew without target" "${sim[@]}" --scenario slew
expect_usage_error "simulate slew below the horizon" "${sim[@]}" --scenario slew --to-az 10 --to-el -20
printf '[station]\ngrid = "FN06"\n[mount.az]\nencoder_bits = 20\n' >"$tmp/bits.toml"
expect_usage_error "simulate bad encoder bits" simulate --config "$tmp/bits.toml" --scenario slew --to-az 1 --to-el 1
printf '[station]\ngrid = "FN06"\n[control]\nwindow_deg = 3\n' >"$tmp/window.toml"
expect_usage_error "simulate window too large" simulate --config "$tmp/window.toml" --scenario slew --to-az 1 --to-el 1

# Satellites (docs/satellites.md): look angles against skyfield's (computed with the same UT1 by
# tests/conformance/skyfield_sat_oracle.py: az 64.06290598896 el -4.43866229916 range 2899.55251 km
# range rate 6.7753018521 km/s), Doppler, passes, the pass simulation, and bad input.
iss=(--tle "$root/tests/data/sat/iss_2024.tle")
sat_station=(--lat 46.2 --lon -79.4 --alt 300)
json_check "sat: skyfield's look angles" \
  "abs(j['az_deg']-64.06290598896)<1e-6 and abs(j['el_deg']+4.43866229916)<1e-6 and abs(j['range_km']-2899.55251)<1e-4 and abs(j['range_rate_km_s']-6.7753018521)<1e-6" \
  sat iss "${iss[@]}" "${sat_station[@]}" --at 2024-03-01T14:00:00Z --dut1 0.1591558755216056 --json
json_check "sat: downlink and uplink Doppler" \
  "abs(j['downlink_hz'] - 437.8e6/(1+j['range_rate_km_s']/299792.458)) < 1e-3 and abs(j['uplink_hz'] - 145.9e6/(1-j['range_rate_km_s']/299792.458)) < 1e-3 and j['downlink_doppler_hz'] < 0" \
  sat 25544 "${iss[@]}" "${sat_station[@]}" --at 2024-03-01T14:00:00Z --downlink-mhz 437.8 --uplink-mhz 145.9 --json
json_check "sat: a refused entry does not hide the good one" "j['sat'] == 'ISS (ZARYA)'" \
  sat "iss (zarya)" --tle "$root/tests/data/sat/mixed.tle" "${sat_station[@]}" --at 2024-03-01T14:00:00Z --json
"$bin" passes iss "${iss[@]}" "${sat_station[@]}" --from 2024-03-01T00:00:00Z --hours 24 --json >"$tmp/passes" 2>"$tmp/err"
"$py" - "$tmp/passes" <<'PY' && ok || bad "passes: $(head -c 300 "$tmp/passes") $(cat "$tmp/err")"
import json, sys
p = [json.loads(l) for l in open(sys.argv[1])]
assert len(p) == 7, len(p)
assert all(x['aos'] < x['tca'] < x['los'] and 0 < x['max_el_deg'] <= 90 for x in p)
assert all(k in p[0] for k in ['aos', 'tca', 'los', 'max_el_deg', 'aos_az_deg', 'los_az_deg'])
assert abs(max(x['max_el_deg'] for x in p) - 54.0) < 0.5
PY
"$bin" passes iss "${iss[@]}" "${sat_station[@]}" --from 2024-03-01T00:00:00Z --hours 24 --mask 0:10,180:20 --json >"$tmp/masked" 2>/dev/null
[ "$(wc -l <"$tmp/masked")" -lt 7 ] && ok || bad "a horizon mask did not remove low passes"
json_check "simulate pass: no unwind, the plant within 2° of the plan" \
  "j['unwinds'] == 0 and j['faults'] == [] and j['max_error_beyond_plan_deg'] < 2 and j['az_travel_deg'] <= j['pass_span_deg'] + 10" \
  "${sim[@]}" --scenario pass "${iss[@]}" --sat iss --from 2024-03-01T13:30:00Z --json
for fmt in json xml kvn csv; do
  json_check "sat from OMM $fmt agrees with the TLE" \
    "abs(j['az_deg']-162.529305592)<1e-6 and abs(j['el_deg']+41.2803344793)<1e-6" \
    sat 25544 --tle "$root/tests/data/omm/catalogue.$fmt" "${sat_station[@]}" --at 2024-03-02T00:00:00Z --json
done
expect_usage_error "sat without --tle" sat iss "${sat_station[@]}"
expect_usage_error "sat not in the file" sat hubble "${iss[@]}" "${sat_station[@]}"
grep -q "hubble" "$tmp/err" && ok || bad "unknown satellite error does not name it: $(cat "$tmp/err")"
expect_usage_error "passes: bad mask" passes iss "${iss[@]}" "${sat_station[@]}" --mask 0:5,x
expect_usage_error "passes: mask out of order" passes iss "${iss[@]}" "${sat_station[@]}" --mask 90:5,10:5
expect_usage_error "sat: no station" sat iss "${iss[@]}"

finish

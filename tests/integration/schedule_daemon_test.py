#!/usr/bin/env python3
"""The daemon following the satellite schedule (docs/satellites.md "The schedule") on the
simulated antenna, with three crafted satellites whose passes skyfield found
(tests/data/sat/schedule_scenario.json: A from t0+20 s to t0+110 s, B of higher priority from
t0+45 s to t0+80 s, C from t0+165 s), the daemon's clock started 15 s before t0:

 1  it switches at each AOS and LOS (within 1.5 s of skyfield's, the state polled every 0.25 s):
    A, then B taking over, A again, then nothing
 2  after the idle time (15 s) it parks, then switches the motors' power off (the simulated
    relay line) once the antenna stands; motion is held while it is off
 3  the power comes on before C's pre-position, and the antenna is at C's AOS point at its AOS
 4  the hooks ([hooks], docs/satellites.md "Hooks") run with the pass in their environment at
    each pre-position, AOS and LOS; the park hook, which sleeps past its 2 s timeout, is killed
    and said in the recent events, while the antenna goes on as planned
 5  a PC program's command holds the schedule

Usage: schedule_daemon_test.py AZELTRACK SCENARIO_DIR"""
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, free_port, http_json, rotctld, wait_until, stop_at_exit

BIN = os.path.realpath(sys.argv[1])
DATA = os.path.realpath(sys.argv[2])
TMP = tempfile.mkdtemp(prefix="azt-schedule-")
LEAD_S = 15.0  # the daemon starts this long before t0 (A's pre-position needs some 13 s)
check = Checks()
procs = []


stop_at_exit(procs, TMP)


def iso_to_unix(text):
    return datetime.datetime.fromisoformat(text.replace("Z", "+00:00")).timestamp()


scenario = json.load(open(os.path.join(DATA, "schedule_scenario.json"), encoding="utf-8"))
t0 = iso_to_unix(scenario["t0"])
sats = {s["name"][-1]: s for s in scenario["satellites"]}
aos = {k: t0 + s["pass"]["aos_s"] for k, s in sats.items()}
los = {k: t0 + s["pass"]["los_s"] for k, s in sats.items()}
site = scenario["site"]

WEB = free_port()
ROT = free_port()
HOOK_LOG = os.path.join(TMP, "hooks.log")
hook = os.path.join(TMP, "note-pass")
with open(hook, "w", encoding="utf-8") as f:
    f.write("#!/bin/sh\n"
            f'printf "%s|%s|%s|%s|%s|%s|%s\\n" "$AZT_EVENT" "$AZT_SAT" "$AZT_NORAD" "$AZT_AOS" '
            f'"$AZT_LOS" "$AZT_MAX_EL" "$(date +%s.%N)" >>{HOOK_LOG}\n')
os.chmod(hook, 0o755)
config = os.path.join(TMP, "schedule.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(f"""schema_version = 2
[station]
lat_deg = {site['lat_deg']}
lon_deg = {site['lon_deg']}
alt_m = {site['alt_m']}
[sky]
dut1_s = {scenario['dut1_s']}
[target]
name = "stop"
[rotctld]
port = {ROT}
[pstrotator]
port = 0
[web]
port = {WEB}
[mount.az]
max_rate_deg_s = 10
[mount.el]
max_rate_deg_s = 10
[satellites]
file = "{os.path.join(DATA, 'schedule_scenario.tle')}"
refuse_days = 3650
stale_days = 3650
idle_park_min = 0.25
[hardware.power]
relay = "sim:1"
on_lead_s = 1
[hooks]
aos = "{hook}"
los = "{hook}"
pre_position = "{hook}"
park = ["/bin/sleep", "60"]
timeout_s = 2
[[schedule]]
sat = "AZT SCENARIO B"
[[schedule]]
sat = "AZT SCENARIO A"
[[schedule]]
sat = "AZT SCENARIO C"
""")
log_path = os.path.join(TMP, "daemon.log")
log = open(log_path, "w", encoding="utf-8")
start_iso = datetime.datetime.fromtimestamp(t0 - LEAD_S, datetime.timezone.utc).strftime(
    "%Y-%m-%dT%H:%M:%SZ")
daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", start_iso],
                          stdout=log, stderr=subprocess.STDOUT)
procs.append(daemon)
base = f"http://127.0.0.1:{WEB}"
if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
    print(open(log_path, encoding="utf-8").read())
    sys.exit("the daemon did not start")


def state():
    return http_json(base, "GET", "/api/state")[1]


def sample():
    s = state()
    sch = s["schedule"] or {}
    step = sch.get("step") or {}
    return {"t": iso_to_unix(s["utc"]), "kind": step.get("kind"),
            "sat": (step.get("sat") or "")[-1:], "power": sch.get("power"),
            "az": s["antenna"].get("az_deg", -999.0), "el": s["antenna"].get("el_deg", -999.0),
            "mode": s["mode"]}


# Poll until C's AOS plus a little: the record of what the station did, by its own clock.
record = []
while True:
    r = sample()
    record.append(r)
    if r["t"] > aos["C"] + 3:
        break
    time.sleep(0.25)


def first(pred, after=0.0):
    return next((r for r in record if r["t"] >= after and pred(r)), None)


def switch_at(kind, sat, after):
    r = first(lambda r: r["kind"] == kind and r["sat"] == sat, after)
    return r["t"] if r else None


# 1: the switches at skyfield's AOS and LOS.
expected = [("A", aos["A"]), ("B", aos["B"]), ("A", los["B"])]
after = t0 - LEAD_S
for sat, when in expected:
    t = switch_at("track", sat, after)
    check(t is not None and abs(t - when) < 1.5,
          f"1: track {sat} from {when - t0:.1f} s after t0 (seen at "
          f"{'never' if t is None else f'{t - t0:.2f}'})")
    after = when
t = first(lambda r: r["kind"] != "track", los["A"] - 2)
check(t is not None and abs(t["t"] - los["A"]) < 1.5, f"1: A ends at its LOS {los['A'] - t0:.1f}")
# 2: park after 15 s idle, then the power off.
park = first(lambda r: r["kind"] == "park", los["A"])
check(park is not None and abs(park["t"] - (los["A"] + 15)) < 1.5,
      f"1: park 15 s after the LOS: {park and park['t'] - t0:.1f}")
off = first(lambda r: r["power"] == "off", los["A"])
check(off is not None, "2: the power goes off")
if off:
    parked = first(lambda r: r["mode"] == "PARK", los["A"])
    check(parked is not None and parked["t"] <= off["t"], "2: parked before the power went off")
    held = [r for r in record if r["t"] > off["t"] and r["power"] == "off"]
    check(len(held) > 4 and max(abs(r["az"] - off["az"]) for r in held) < 0.2,
          f"2: the antenna still while the power is off ({len(held)} samples)")
# 3: on again before C's pre-position; at C's AOS point at its AOS.
on = first(lambda r: r["power"] == "on", off["t"] if off else los["A"])
pre = switch_at("preposition", "C", los["A"])
check(on is not None and pre is not None and on["t"] <= pre + 0.5,
      f"3: power on ({on and on['t'] - t0:.1f}) before C's pre-position ({pre and pre - t0:.1f})")
at_aos = first(lambda r: r["t"] >= aos["C"])
c = sats["C"]["pass"]
check(at_aos is not None and abs(at_aos["az"] - c["aos_az_deg"]) < 1.0 and at_aos["el"] < 1.0,
      f"3: at C's AOS point ({c['aos_az_deg']:.1f}°) at its AOS: {at_aos}")
t = switch_at("track", "C", aos["C"] - 2)
check(t is not None and abs(t - aos["C"]) < 1.5, f"3: track C at its AOS ({t and t - t0:.1f})")
# 4: the hooks, in the order of the station's steps, with each pass's own figures.
hooks = [line.strip().split("|") for line in open(HOOK_LOG, encoding="utf-8")]
print("4: hooks:", [h[:3] for h in hooks])
# Each step's hooks, in the steps' order; the hooks of one instant (B's take-over ends A's pass as
# B's begins) run side by side, so their lines may come in either order.
want = [{("pre_position", "A")}, {("aos", "A")}, {("los", "A"), ("aos", "B")},
        {("los", "B"), ("aos", "A")}, {("los", "A")}, {("pre_position", "C")}, {("aos", "C")}]
steps = []
for h in sorted(hooks, key=lambda h: float(h[6])):
    if steps and float(h[6]) - steps[-1][0] < 0.5:
        steps[-1][1].add((h[0], h[1][-1:]))
    else:
        steps.append((float(h[6]), {(h[0], h[1][-1:])}))
check([events for _, events in steps] == want, "4: the hooks' events in the steps' order")
for h in hooks:
    p = sats[h[1][-1:]]
    right = (h[2] == str(p["norad"]) and abs(iso_to_unix(h[3]) - aos[h[1][-1:]]) < 1.0 and
             abs(iso_to_unix(h[4]) - los[h[1][-1:]]) < 1.0 and
             abs(float(h[5]) - p["pass"]["max_el_deg"]) < 0.05)
    check(right, f"4: {h[0]} {h[1]}: NORAD, AOS, LOS and max el are the pass's: {h}")
events = " | ".join(e["text"] for e in state()["events"])
check(events.count("killed after its 2 s timeout") >= 1, "4: the sleeping park hook is killed")

# 5: a PC program takes the antenna; the schedule steps aside (and says who holds it).
print("5: rotctld P 200 10:", rotctld(ROT, ["P 200 10"]))
check(wait_until(lambda: ((state()["schedule"] or {}).get("held_by") or "").startswith("rotctld"), 3),
      f"5: held by the program's command: {state()['schedule']}")
check(state()["mode"] == "EXT", "5: the program's position is followed, not C")
check(daemon.poll() is None, "the daemon runs on")
print(json.dumps(record[::8]))
sys.exit(check.summary("schedule_daemon_test"))

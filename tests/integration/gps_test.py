#!/usr/bin/env python3
"""The GPS of docs/gps.md against a real `azeltrack serve`, gpsd and gpsfake on loopback (no GPS
hardware): the daemon's `gps` state through every phase of a receiver's life, the station's
position surveyed from a held fix and saved, and a jump while tracking refused.

 1  gpsd not running: state no_gpsd, the daemon runs on
 2  gpsfake replays a good u-blox fix: fix3d with every field; use_position adopts the average,
    within 1 m of the log's mean, and saves it as [station] lat_deg/lon_deg/alt_m
 3  the log ends (the receiver stops talking): no_fix; gpsd killed: no_gpsd, the daemon runs on
 4  a log with no fix, then a 2D fix, then garbage lines between good fixes: no_fix, fix2d, fix3d
 5  a position jump of 500 m while tracking: not adopted, shown in jump_refused; gpsd killed
    and restarted while tracking: no_gpsd, the Moon still tracked, gpsd found again

Usage: gps_test.py AZELTRACK"""
import atexit
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from daemon_harness import (Checks, free_port, http_json, remove_gpsd_shm, station_toml,
                            wait_until)

BIN = os.path.realpath(sys.argv[1])
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
LOGS = os.path.join(ROOT, "tests", "data", "gps")
TMP = tempfile.mkdtemp(prefix="azt-gps-")
check = Checks()
procs = []


def stop(p):
    """Ends a gpsfake and the gpsd it started (its process group)."""
    try:
        os.killpg(p.pid, signal.SIGKILL)  # gpsfake waits on its gpsd otherwise
    except ProcessLookupError:
        pass
    p.wait(10)


def cleanup():
    for p in procs:
        if getattr(p, "group", False):
            stop(p)
        elif p.poll() is None:
            p.send_signal(signal.SIGTERM)
            try:
                p.wait(5)
            except subprocess.TimeoutExpired:
                p.kill()
    for port in gpsd_ports:
        remove_gpsd_shm(port)
    shutil.rmtree(TMP, ignore_errors=True)


atexit.register(cleanup)
gpsd_ports = set()


def start_daemon(name, gpsd_port, target, hold_s):
    web = free_port()
    config = os.path.join(TMP, name + ".toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web).replace('name = "stop"', f'name = "{target}"'))
        f.write(f'[gps]\nenabled = true\ngpsd = "127.0.0.1:{gpsd_port}"\nuse_position = true\n'
                f"hold_s = {hold_s}\nmin_sats = 4\njump_m = 100\n")
    log = open(os.path.join(TMP, name + ".log"), "w", encoding="utf-8")
    p = subprocess.Popen([BIN, "serve", "--config", config], stdout=log, stderr=subprocess.STDOUT)
    procs.append(p)
    base = f"http://127.0.0.1:{web}"
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        print(open(log.name, encoding="utf-8").read())
        sys.exit("the daemon did not start")
    return p, base, config, log.name


def gpsfake(port, log_name, cycle=0.02):
    """gpsd on `port` fed once with the log, a sentence every `cycle` s (8 sentences a fix)."""
    gpsd_ports.add(port)
    p = subprocess.Popen(["gpsfake", "-q", "-1", "-c", str(cycle), "-P", str(port),
                          os.path.join(LOGS, log_name + ".nmea")],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                         start_new_session=True, env={**os.environ, "TMPDIR": TMP})
    p.group = True
    procs.append(p)
    return p


def gps(base):
    return http_json(base, "GET", "/api/state")[1]["gps"]


def until_state(base, state, seconds=15):
    return wait_until(lambda: gps(base)["state"] == state, seconds)


def distance_m(lat1, lon1, lat2, lon2):
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dp, dl = p2 - p1, math.radians(lon2 - lon1)
    h = math.sin(dp / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    return 2 * 6371008.8 * math.asin(math.sqrt(h))


def truth(name):
    with open(os.path.join(LOGS, name + ".json"), encoding="utf-8") as f:
        return json.load(f)["mean"]


# 1: no gpsd yet. The log opens with 40 s without a fix, so the daemon (retrying every 2 s) is
# connected before the first good one; the survey holds 40 of the 60 fixes (σ 1.5 m each), so its
# mean is within ~0.2 m of the whole log's.
GPSD = free_port()
daemon, base, config, log = start_daemon("survey", GPSD, "stop", 40.0)
check(until_state(base, "no_gpsd", 5), "1: no_gpsd while nothing listens")
check(daemon.poll() is None, "1: the daemon runs on without gpsd")

# 2: a good fix, surveyed and saved.
fake = gpsfake(GPSD, "good_fix")
check(until_state(base, "fix3d", 15), f"2: fix3d from gpsfake: {gps(base)}")
# gpsd's first report of a sky may come before its first GSA: wait for the satellites in use.
wait_until(lambda: gps(base)["sats_used"] == 8, 5)
g = gps(base)
mean = truth("good_fix")
check(g["sats_used"] == 8 and g["sats_visible"] == 12, f"2: satellites 8 of 12: {g}")
check(g["hdop"] == 0.94, f"2: hdop 0.94: {g['hdop']}")
check(str(g["time_utc"]).startswith("2025-03-14T00:0"), f"2: the receiver's time: {g['time_utc']}")
check(distance_m(g["lat_deg"], g["lon_deg"], mean[0], mean[1]) < 10, f"2: the fix: {g}")
check(abs(g["alt_m"] - mean[2]) < 10, f"2: altitude above sea level: {g['alt_m']}")
check(len(g["satellites"]) == 12 and sum(s["used"] for s in g["satellites"]) == 8,
      "2: the sky of satellites")
check(wait_until(lambda: gps(base)["position_in_use"], 15), f"2: position adopted: {gps(base)}")

# 3: the log ends: the receiver has stopped talking (no_fix); then gpsd is killed (no_gpsd), and
# the station carries on.
check(until_state(base, "no_fix", 30), f"3: no_fix once the receiver stopped talking: {gps(base)}")
stop(fake)
check(until_state(base, "no_gpsd", 10), f"3: no_gpsd after gpsd was killed: {gps(base)}")
station = http_json(base, "GET", "/api/state")[1]["station"]
off = distance_m(station["lat_deg"], station["lon_deg"], mean[0], mean[1])
print(f"measure: surveyed position {off:.2f} m from the log's mean")
check(off < 1.0, f"2: the station's position within 1 m of the log's mean ({off:.2f} m)")
saved = open(config, encoding="utf-8").read().split("[station]")[1].split("[")[0]
check("lat_deg" in saved and "alt_m" in saved and "grid" not in saved,
      f"2: saved as [station] lat_deg/lon_deg/alt_m: {saved}")
check(daemon.poll() is None, "3: the daemon runs on")

# 4: no fix, a 2D fix, garbage between good fixes: gpsd restarted, found again within 5 s.
for name, state in [("no_fix", "no_fix"), ("fix_2d", "fix2d"), ("garbage", "fix3d")]:
    t0 = time.monotonic()
    fake = gpsfake(GPSD, name, cycle=0.05)
    check(until_state(base, state, 15), f"4: {name}: {state}: {gps(base)}")
    if name == "no_fix":
        print(f"measure: gpsd restarted: {state} after {time.monotonic() - t0:.1f} s")
        check(time.monotonic() - t0 < 5 + 2, "4: gpsd found again within 5 s (+ its start)")
    stop(fake)  # gpsd killed mid-run
    check(until_state(base, "no_gpsd", 10), f"4: no_gpsd after {name}'s gpsd was killed")
check(daemon.poll() is None, "4: the daemon runs on")
daemon.send_signal(signal.SIGTERM)
daemon.wait(10)

# 5: tracking the Moon, the fix jumps 500 m: the first site is adopted, the jump is not.
GPSD2 = free_port()
daemon, base, config, log = start_daemon("jump", GPSD2, "moon", 1.0)
fake = gpsfake(GPSD2, "position_jump", cycle=0.02)
check(wait_until(lambda: gps(base)["position_in_use"], 20), f"5: first site adopted: {gps(base)}")
before = http_json(base, "GET", "/api/state")[1]["station"]
jump = truth("position_jump")
check(distance_m(before["lat_deg"], before["lon_deg"], *jump["before"][:2]) < 5,
      f"5: the first site is the first half's: {before}")
check(wait_until(lambda: gps(base)["jump_refused"] is not None, 20), f"5: jump refused: {gps(base)}")
after = http_json(base, "GET", "/api/state")[1]["station"]
# The first site is refined as its fixes come in (moves of metres are adopted), the 500 m is not.
check(distance_m(after["lat_deg"], after["lon_deg"], *jump["before"][:2]) < 5,
      f"5: the station did not jump while tracking: {after}")
refused = gps(base)["jump_refused"]
check(distance_m(refused["lat_deg"], refused["lon_deg"], *jump["after"][:2]) < 5,
      f"5: the refused site is the second half's: {refused}")
check("while tracking" in open(log, encoding="utf-8").read(), "5: the jump is logged")
stop(fake)  # gpsd killed mid-run while tracking: the GPS is gone, the tracking is not
check(until_state(base, "no_gpsd", 10), f"5: no_gpsd after gpsd was killed: {gps(base)}")
state = http_json(base, "GET", "/api/state")[1]
check(state["mode"] == "TRACK" and state["target"]["name"].lower() == "moon",
      f"5: the Moon is still tracked without gpsd: {state['mode']} {state['target']}")
fake = gpsfake(GPSD2, "good_fix")
check(until_state(base, "no_fix", 10), f"5: gpsd back: found again: {gps(base)}")
stop(fake)

sys.exit(check.summary("gps"))

#!/usr/bin/env python3
"""Noise measurements from the API (docs/calibration.md "Sun noise and the figure of merit") on
`azeltrack serve`'s simulated antenna with the simulated receiver (`[receiver] source = "sim"`): a
POST /api/noise of Cassiopeia A measures its Y-factor against cold sky either side, through the
station's front door, within 0.2 dB of what the core's formula expects from Perley & Butler's
flux and the dish (the simulated receiver hears a point source by the same η·A·S/2k), the result
is appended to noise-log.jsonl beside the configuration, a bad field is refused naming it with
nothing moved, and a STOP ends a running measurement. The daemon runs at a fixed instant
(daemon_harness.FIXED_UTC: Cas A at 58° of elevation). About 40 s. Usage: noise_api_test.py
AZELTRACK"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile

from daemon_harness import FIXED_UTC, Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-noise-")
check = Checks()

web = free_port()
config = os.path.join(TMP, "noise.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=web, mount_rate_deg_s=8.0))
    f.write('[receiver]\nsource = "sim"\n')
    # A 25 m dish at 1296 MHz (T_sys 50 K, 60 %): Cas A's 1876 Jy give 200 K, 7.0 dB. The beam is
    # the simulation's 2° (wider than a 25 m dish's; a point source's rise does not depend on it).
    f.write("[sim.receiver]\nbeamwidth_deg = 2.0\ndish_m = 25.0\nnoise_db = 0.05\n")
    # The antenna starts near Cas A (az 312°, el 58° at FIXED_UTC): no long slew first.
    f.write("[sim.az]\nstart_deg = 305.0\n[sim.el]\nstart_deg = 55.0\n")
token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                       capture_output=True).stdout.decode().strip()
base = f"http://127.0.0.1:{web}"
log = open(os.path.join(TMP, "serve.log"), "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", FIXED_UTC], stdout=log,
                          stderr=subprocess.STDOUT)
# Two pairs, the cold sky 2 beamwidths off (the shortest moves the plan allows), short dwells.
MEASURE = {"source": "casa", "beamwidth_deg": 2.0, "offset_beams": 2.0, "repeats": 2,
           "settle_s": 0.5, "dwell_s": 1.0,
           "dish_m": 25.0, "efficiency": 0.6, "tsys_k": 50.0, "freq_mhz": 1296}


def state():
    return http_json(base, "GET", "/api/state")[1]


try:
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start: " + open(log.name, encoding="utf-8").read())
    check(wait_until(lambda: state()["receiver"]["state"] == "receiving", 5), "the receiver reads")
    check(state()["noise"]["state"] == "idle", "no measurement at the start")

    code, body = http_json(base, "POST", "/api/noise", dict(MEASURE, offset_beams=1.0), token)
    check(code == 400 and body.get("field") == "offset_beams",
          f"an offset inside the beam is refused naming the field: {code} {body}")
    check(state()["mode"] == "STOP" and state()["noise"]["state"] == "idle", "nothing moved")

    code, body = http_json(base, "POST", "/api/noise", MEASURE, token)
    check(code == 200 and body.get("noise", {}).get("state") == "running",
          f"the measurement of Cas A started: {code} {body}")
    finished = wait_until(lambda: state()["noise"]["state"] != "running", 150, 0.5)
    n = state()["noise"]
    result = n.get("result", {})
    expected = result.get("expected", {})
    print(f"noise of {n['source']}: {n['state']}, Y {result.get('y_factor_db')} ± "
          f"{result.get('std_error_db')} dB, expected {expected.get('y_db')} dB "
          f"({expected.get('flux_sfu')} SFU), {n.get('reason')}")
    check(finished and n["state"] == "done", f"the measurement ends with a result: {n}")
    check(n["steps_done"] == 4 and [s["on"] for s in n["steps"]] == [True, False, True, False],
          f"on, off, on, off: {n.get('steps')}")
    check(abs(result.get("y_factor_db", 0) - expected.get("y_db", 99)) <= 0.2,
          f"Y within 0.2 dB of the expected {expected.get('y_db')}: {result}")
    check(result.get("std_error_db", 1) < 0.1, f"a small scatter: {result}")

    path = os.path.join(TMP, "noise-log.jsonl")
    check(wait_until(lambda: os.path.exists(path), 5), "the noise log is written")
    lines = open(path, encoding="utf-8").read().splitlines() if os.path.exists(path) else []
    logged = json.loads(lines[0]) if lines else {}
    check(len(lines) == 1 and logged.get("y_factor_db") == result.get("y_factor_db")
          and logged.get("utc", "").startswith("20") and logged.get("source") == n["source"],
          f"one line logged with its UTC: {lines}")

    code, body = http_json(base, "POST", "/api/noise", MEASURE, token)
    check(code == 200, f"a second measurement starts: {code} {body}")
    check(http_json(base, "POST", "/api/stop", {}, token)[0] == 200, "STOP")
    check(wait_until(lambda: state()["noise"]["state"] == "stopped", 5),
          f"STOP ends the measurement: {state()['noise']}")
    lines = open(path, encoding="utf-8").read().splitlines()
    check(len(lines) == 1, f"a stopped measurement logs nothing: {lines}")
    daemon.send_signal(signal.SIGTERM)
    check(daemon.wait(10) == 0, "exits cleanly")
finally:
    if daemon.poll() is None:
        daemon.kill()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("noise_api"))

#!/usr/bin/env python3
"""A station whose elevation does not move ([mount.el] fixed_deg, docs/eme.md "Fixed-elevation
arrays") against a real `azeltrack serve` on the simulated antenna: rotctld reports the fixed
angle and a client's elevation moves azimuth only, /api/state shows the fixed angle and whether
the target is in the beam, the Moon planner keeps to the beam, and the direction test refuses the
elevation it does not have.

Usage: one_axis_test.py AZELTRACK"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile

from daemon_harness import (FIXED_UTC, Checks, free_port, http_json, rotctld, station_toml,
                            wait_until)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-one-axis-")
check = Checks()
daemon = None
try:
    web, rot = free_port(), free_port()
    config = os.path.join(TMP, "station.toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web, rotctld_port=rot))
        f.write('[sky]\ndx_grid = "JO62QM"\n[mount.az]\nmax_rate_deg_s = 6.0\n'
                '[mount.el]\nfixed_deg = 12.0\nbeam_width_deg = 20.0\n')
    # The daemon reads its tokens as it starts: this one is made first.
    token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                           capture_output=True, text=True).stdout.strip()
    log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
    daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", FIXED_UTC],
                              stdout=log, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{web}"
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[1]["antenna"]["known"], 30):
        sys.exit("the daemon did not start")

    state = http_json(base, "GET", "/api/state")[1]
    check(state["antenna"]["el_fixed_deg"] == 12.0 and state["antenna"]["el_deg"] == 12.0,
          f"/api/state: the fixed elevation: {state['antenna']}")
    reply = rotctld(rot, ["p"])[0].split()
    check(len(reply) == 2 and abs(float(reply[1]) - 12.0) < 1e-6, f"rotctld p: {reply}")

    # A client asks for 40° of elevation: azimuth turns, elevation is what it is.
    check(rotctld(rot, ["P 60 40"])[0] == "RPRT 0", "rotctld P accepted")
    arrived = wait_until(
        lambda: abs(float(rotctld(rot, ["p"])[0].split()[0]) - 60.0) < 1.0, 30)
    az, el = (float(x) for x in rotctld(rot, ["p"])[0].split())
    check(arrived and abs(el - 12.0) < 1e-6, f"at azimuth 60 with the elevation fixed: {az} {el}")
    state = http_json(base, "GET", "/api/state")[1]
    check(isinstance(state["target"].get("in_beam"), bool) and state["target"]["in_beam"] is False,
          f"a 40° target is outside a 12° ± 10° beam: {state['target']}")
    check(state["faults"] == [], f"no faults: {state['faults']}")

    status, body = http_json(base, "GET",
                             "/api/moon-windows?days=3&from=2025-03-01T00:00:00Z", timeout=30)
    check(status == 200 and body.get("el_band_deg") == [2.0, 22.0]
          and all(2.0 <= w["el_deg"] <= 22.0 for w in body["windows"]) and body["windows"],
          f"the planner keeps to the beam: {status} {body.get('el_band_deg')} "
          f"{[w['el_deg'] for w in body.get('windows', [])]}")

    status, body = http_json(base, "POST", "/api/hardware/direction-test", {"axis": "el"},
                             token=token)
    check(status in (400, 409) and "fixed" in body.get("error", ""),
          f"no elevation to test: {status} {body}")
    check(daemon.poll() is None, "the daemon runs on")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)
finally:
    if daemon is not None and daemon.poll() is None:
        daemon.kill()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("one_axis"))

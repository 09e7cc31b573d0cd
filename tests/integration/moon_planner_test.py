#!/usr/bin/env python3
"""GET /api/moon-windows (docs/eme.md) against a real `azeltrack serve`: the same windows as the
command line (both with ERFA's ephemeris), bad values refused by name, and the control loop
answering while a 60-day search runs on the worker.

Usage: moon_planner_test.py AZELTRACK"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-planner-")
check = Checks()
try:
    web = free_port()
    config = os.path.join(TMP, "station.toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web).replace('name = "stop"', 'name = "moon"'))
        f.write('[sky]\nband = "1296"\ndx_grid = "JO62QM"\n')
    log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
    daemon = subprocess.Popen([BIN, "serve", "--config", config], stdout=log,
                              stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{web}"
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start")

    query = "/api/moon-windows?days=5&from=2025-03-01T00:00:00Z&min_el=5&dx_min_el=10"
    status, body = http_json(base, "GET", query, timeout=30)
    check(status == 200, f"the planner answers: {status} {body}")
    cli = json.loads(subprocess.run(
        [BIN, "moon-windows", "--grid", "FN06HE", "--dx-grid", "JO62QM", "--from",
         "2025-03-01T00:00:00Z", "--days", "5", "--min-el", "5", "--dx-min-el", "10", "--band",
         "1296", "--ephemeris", "erfa", "--json"], capture_output=True, text=True,
        check=True).stdout)
    check(body["dx_grid"] == "JO62QM" and body["band"] == "1296",
          f"the station's DX and band by default: {body['dx_grid']} {body['band']}")
    check([w["start"] for w in body["windows"]] == [w["start"] for w in cli["windows"]] and
          [w["dgrd_db"] for w in body["windows"]] == [w["dgrd_db"] for w in cli["windows"]],
          f"the command line's windows: {len(body['windows'])} vs {len(cli['windows'])}")
    check(len(body["windows"]) >= 4, f"five days, a window a day: {len(body['windows'])}")

    for bad, field in [("dx_grid=ZZ99", "dx_grid"), ("days=500", "days"), ("min_el=nan", "min_el"),
                       ("band=7", "band"), ("from=yesterday", "from")]:
        status, body = http_json(base, "GET", "/api/moon-windows?" + bad)
        check(status == 400 and body.get("field") == field, f"{bad}: 400 naming {field}: {status} {body}")

    # A 60-day search runs on the worker: the loop answers meanwhile.
    slowest, done = [0.0], threading.Event()

    def poll():
        while not done.is_set():
            t0 = time.monotonic()
            http_json(base, "GET", "/api/state")
            slowest[0] = max(slowest[0], time.monotonic() - t0)

    poller = threading.Thread(target=poll)
    poller.start()
    t0 = time.monotonic()
    status, body = http_json(base, "GET", "/api/moon-windows?days=60", timeout=60)
    took = time.monotonic() - t0
    done.set()
    poller.join()
    print(f"measure: 60 days in {took:.2f} s; slowest /api/state meanwhile {slowest[0] * 1000:.0f} ms")
    check(status == 200 and len(body["windows"]) > 40, f"60 days: {status}")
    check(slowest[0] < 0.25, f"the loop answered within 250 ms while searching: {slowest[0]:.3f} s")
    check(daemon.poll() is None, "the daemon runs on")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)
finally:
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("moon_planner"))

#!/usr/bin/env python3
"""A dish whose elevation is a pulse-counted linear actuator (examples/actuator_dish.toml's
[hardware.el], docs/hardware.md "Pulse sensors and homing") against a real `azeltrack serve` on
the simulated antenna: the elevation homes at start (/api/state antenna.axes.el: seeking, then
homed), the console's STOP ends a homing, POST /api/hardware/home starts another and is refused
for an axis without a count, and once homed the dish goes where it is sent.

Usage: pulse_homing_test.py AZELTRACK"""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

from daemon_harness import FIXED_UTC, Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
TMP = tempfile.mkdtemp(prefix="azt-pulse-homing-")
check = Checks()
daemon = None


def dish_tables():
    """The example's [geometry], [mount.el], [hardware.el] and [sim.el], the dish starting near
    its home switch (5.83°) so that homing takes seconds."""
    with open(os.path.join(SOURCE, "examples", "actuator_dish.toml"), encoding="utf-8") as f:
        text = f.read()
    tables = text[text.index("[geometry]"):]
    tables = tables.replace("[mount.az]\nmax_rate_deg_s = 1.0\n", "")
    return re.sub(r"start_deg = [0-9.]+", "start_deg = 9.0", tables)


try:
    web = free_port()
    config = os.path.join(TMP, "station.toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web) + dish_tables())
    token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                           capture_output=True, text=True).stdout.strip()
    log = open(os.path.join(TMP, "daemon.log"), "w", encoding="utf-8")
    daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", FIXED_UTC],
                              stdout=log, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{web}"

    def el_axis():
        return http_json(base, "GET", "/api/state")[1]["antenna"].get("axes", {}).get("el", {})

    if not wait_until(lambda: el_axis().get("homing") is not None, 30):
        sys.exit("the daemon did not start with a pulse-counted elevation")
    # The state may be served before the first control tick has begun the homing.
    homing = ("seeking", "stopping", "backing off", "re-approaching")
    started = wait_until(lambda: el_axis()["homing"] in homing, 10)
    first = el_axis()
    check(started and isinstance(first.get("pulse_count"), int),
          f"the elevation homes at start: {first}")

    # The console's STOP ends the homing: the axis holds, unreferenced, saying why.
    status, _ = http_json(base, "POST", "/api/stop", {}, token=token)
    stopped = wait_until(lambda: el_axis()["homing"] == "not homed", 5)
    held = el_axis().get("held") or ""
    check(status == 200 and stopped and "stopped by" in held, f"STOP ends homing: {el_axis()}")

    status, body = http_json(base, "POST", "/api/hardware/home", {"axis": "az"}, token=token)
    check(status == 409 and "no pulse sensor" in body.get("error", ""),
          f"the azimuth has no count to home: {status} {body}")
    status, body = http_json(base, "POST", "/api/hardware/home", {"axis": "pol"}, token=token)
    check(status == 409 and "no pulse sensor" in body.get("error", ""),
          f"no pol axis here to home: {status} {body}")
    status, body = http_json(base, "POST", "/api/hardware/home", {"axis": "feed"}, token=token)
    check(status == 400, f"not an axis: {status} {body}")
    status, body = http_json(base, "POST", "/api/hardware/home", {"axis": "el"}, token=token)
    check(status == 200 and body.get("axis") == "el", f"homing again: {status} {body}")
    homed = wait_until(lambda: el_axis()["homing"] == "homed", 60)
    check(homed and el_axis().get("held") is None, f"homed: {el_axis()}")

    # Referenced: the dish goes where it is sent, by its count.
    status, _ = http_json(base, "POST", "/api/target", {"az_deg": 180.0, "el_deg": 20.0},
                          token=token)
    arrived = wait_until(
        lambda: abs(http_json(base, "GET", "/api/state")[1]["antenna"]["el_deg"] - 20.0) < 0.6, 60)
    state = http_json(base, "GET", "/api/state")[1]
    check(status == 200 and arrived, f"at 20° by the count: {state['antenna']}")
    check(state["faults"] == [], f"no faults: {state['faults']}")
    check(daemon.poll() is None, "the daemon runs on")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)
finally:
    if daemon is not None and daemon.poll() is None:
        daemon.kill()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("pulse_homing"))

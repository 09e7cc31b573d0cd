#!/usr/bin/env python3
"""[export] azel_dat (docs/eme.md) against a real `azeltrack serve` tracking the Moon: the file
appears within seconds in WSJT-X's four-line format, its Moon and Sun match the console's state,
it is rewritten every second (never seen torn by a reader polling it), and a path that cannot be
written is logged once while the daemon tracks on.

Usage: azel_dat_test.py AZELTRACK"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-azel-")
check = Checks()


def start(name, azel_path, extra="", export_extra=""):
    web = free_port()
    config = os.path.join(TMP, name + ".toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web).replace('name = "stop"', 'name = "moon"'))
        f.write(f'[sky]\nband = "432"\n{extra}[export]\nazel_dat = "{azel_path}"\n{export_extra}')
    log = open(os.path.join(TMP, name + ".log"), "w", encoding="utf-8")
    p = subprocess.Popen([BIN, "serve", "--config", config], stdout=log, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{web}"
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start: " + open(log.name, encoding="utf-8").read())
    return p, base, log.name


def parse(text):
    lines = text.splitlines()
    if len(lines) != 4:
        return None
    places = [line.split(",") for line in lines[:3]]
    return {"clock": places[0][0], "moon": (float(places[0][1]), float(places[0][2])),
            "sun": (float(places[1][1]), float(places[1][2])), "names": [p[3] for p in places],
            "doppler": lines[3].split(",")}


try:
    path = os.path.join(TMP, "azel.dat")
    daemon, base, log = start("good", path)
    check(wait_until(lambda: os.path.exists(path), 5), "the file appears")
    first = parse(open(path, encoding="ascii").read())
    check(first is not None and first["names"] == ["Moon", "Sun", "Source"],
          f"WSJT-X's four lines: {first}")
    state = http_json(base, "GET", "/api/state")[1]
    moon, sun = state["moon"], state["sun"]
    # The state and the file may be a second apart: the Moon moves < 0.01° a second.
    check(abs(first["moon"][0] - moon["az_deg"]) < 0.15 and abs(first["moon"][1] - moon["el_deg"]) < 0.15,
          f"the Moon as the console shows it: {first['moon']} vs {moon['az_deg']}, {moon['el_deg']}")
    check(abs(first["sun"][0] - sun["az_deg"]) < 0.15, f"the Sun: {first['sun']} vs {sun}")
    check(first["doppler"][0].strip() == "432" and abs(
        float(first["doppler"][3]) - moon["echo_doppler_hz"]) < 2.0,
          f"432 MHz and the self echo: {first['doppler']} vs {moon['echo_doppler_hz']}")
    # Rewritten every second; a reader polling meanwhile never sees a partial file.
    seen, torn, end = set(), 0, time.monotonic() + 3.5
    while time.monotonic() < end:
        try:
            parsed = parse(open(path, encoding="ascii").read())
        except FileNotFoundError:
            parsed = None
        if parsed is None:
            torn += 1
        else:
            seen.add(parsed["clock"])
    check(len(seen) >= 3, f"a new second at least every second: {sorted(seen)}")
    check(torn == 0, f"never torn or missing while polled: {torn}")
    check(os.listdir(TMP).count("azel.dat.bak") == 0, "no backup files for a per-second file")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)

    # [export] azel_dat_pol_line: WSJT-X's fifth line, its Dpol the state's (DX in Europe).
    path = os.path.join(TMP, "azel-pol.dat")
    daemon, base, log = start("pol", path, 'dx_grid = "JO62"\n', "azel_dat_pol_line = true\n")
    check(wait_until(lambda: os.path.exists(path), 5), "the file with the Pol line appears")
    lines = open(path, encoding="ascii").read().splitlines()
    dpol = http_json(base, "GET", "/api/state")[1]["moon"].get("dpol_deg")
    check(len(lines) == 5 and lines[4].endswith(",Pol") and dpol is not None
          and abs(float(lines[4].split(",")[0]) - dpol) < 0.15,
          f"five lines, Dpol {lines[4:]} as the state's {dpol}")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)

    bad = os.path.join(TMP, "no-such-folder", "azel.dat")
    daemon, base, log = start("bad", bad)
    check(wait_until(lambda: "azel.dat: not written" in open(log, encoding="utf-8").read(), 5),
          "an unwritable path is logged")
    wait_until(lambda: http_json(base, "GET", "/api/state")[1]["mode"] == "TRACK", 5)
    state = http_json(base, "GET", "/api/state")[1]
    check(state["mode"] == "TRACK" and daemon.poll() is None, "the daemon tracks on")
    # Three more seconds of failing writes (the loop runs: the console answers meanwhile).
    end = time.monotonic() + 3.0
    while time.monotonic() < end:
        http_json(base, "GET", "/api/state")
    check(open(log, encoding="utf-8").read().count("azel.dat: not written") == 1,
          "said once, not every second")
    daemon.send_signal(signal.SIGTERM)
    daemon.wait(10)
finally:
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("azel_dat"))

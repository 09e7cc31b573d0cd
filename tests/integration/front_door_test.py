#!/usr/bin/env python3
"""The station's one front door (docs/daemon.md) against a real `azeltrack serve`: the console and a
PC program (rotctld) get the same answer for the same target on a 0–450° mount at 400° (taken),
at 500° (refused as a bad value) and while a fault is latched (refused as "not now", the same
reason in the console and in the daemon's record); every accepted motion command is listed with
its source in /api/state "commands".
Usage: front_door_test.py AZELTRACK"""
import os
import shutil
import subprocess
import sys
import tempfile

from daemon_harness import Checks, free_port, http_json, rotctld, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-front-door-")
check = Checks()


def config(path, web_port, rot_port, fault):
    with open(path, "w") as f:
        # A 0–450° mount; the jammed station's azimuth shaft never turns (the stall latches).
        f.write(station_toml(web_port, rot_port, mount_rate_deg_s=10.0) + f"""[geometry]
az_min_deg = 0.0
az_max_deg = 450.0
[sim.az]
{'fault = "frozen_shaft"' if fault else ''}
""")


class Station:
    def __init__(self, name, fault):
        self.web, self.rot = free_port(), free_port()
        self.base = f"http://127.0.0.1:{self.web}"
        self.path = os.path.join(TMP, f"{name}.toml")
        config(self.path, self.web, self.rot, fault)
        self.token = subprocess.run([BIN, "web", "token", "--config", self.path], check=True,
                                    capture_output=True).stdout.decode().strip()
        self.log = open(os.path.join(TMP, f"{name}.log"), "w")
        self.proc = subprocess.Popen([BIN, "serve", "--config", self.path], stdout=self.log,
                                     stderr=self.log)
        check(wait_until(lambda: self.state()["antenna"]["known"], 15), f"{name}: started")

    def state(self):
        return http_json(self.base, "GET", "/api/state")[1]

    def console_target(self, az, el):
        return http_json(self.base, "POST", "/api/target", {"az_deg": az, "el_deg": el},
                         self.token)

    def program_target(self, az, el):
        return rotctld(self.rot, [f"P {az} {el}"])[0]

    def stop(self):
        self.proc.terminate()
        self.proc.wait(10)
        self.log.close()


def refusals(station):
    return [e["text"] for e in station.state()["events"] if ": refused: " in e["text"]]


try:
    healthy = Station("healthy", fault=False)
    # 400° on a 0–450° mount: both take it (the console as MAN, the program as EXT).
    code, body = healthy.console_target(400, 10)
    check(code == 200 and body.get("mode") == "MAN", f"console at 400°: {code} {body}")
    reply = healthy.program_target(400, 10)
    check(reply == "RPRT 0", f"rotctld at 400°: {reply}")
    # 500°: both refuse it as a bad value, for the same reason.
    code, body = healthy.console_target(500, 10)
    check(code == 400 and body.get("field") == "az_deg", f"console at 500°: {code} {body}")
    reply = healthy.program_target(500, 10)
    check(reply == "RPRT -1", f"rotctld at 500°: {reply}")  # RIG_EINVAL
    texts = refusals(healthy)
    check(len(texts) == 2 and texts[0].split(": refused: ")[1] == body.get("error"),
          f"the same reason in the console and the record: {texts} / {body}")
    # Who moved the antenna: each accepted command with its source, newest first.
    commands = [c["text"] for c in healthy.state()["commands"]]
    check(len(commands) == 2 and commands[0].startswith("rotctld 127.0.0.1:") and
          "az 400.00°" in commands[0] and commands[1].startswith("console 127.0.0.1: position"),
          f"accepted commands listed with their sources: {commands}")
    check(healthy.state()["who"].startswith("rotctld 127.0.0.1:"), "the commander is the program")
    healthy.stop()

    jammed = Station("jammed", fault=True)
    check(jammed.program_target(40, 10) == "RPRT 0", "the first move is taken")
    check(wait_until(lambda: jammed.state()["faults"], 10), "the frozen shaft latches a stall")
    code, body = jammed.console_target(400, 10)
    check(code == 409 and "a fault is latched" in body.get("error", ""),
          f"console while latched: {code} {body}")
    reply = jammed.program_target(400, 10)
    check(reply == "RPRT -9", f"rotctld while latched: {reply}")  # RIG_ERJCTED (not now)
    texts = refusals(jammed)
    check(len(texts) >= 2 and all(t.split(": refused: ")[1] == body.get("error")
                                  for t in texts[:2]),
          f"the same refusal for both: {texts[:2]} / {body}")
    code, body = http_json(jammed.base, "POST", "/api/target", {"name": "moon"}, jammed.token)
    check(code == 409, f"tracking while latched is refused too: {code} {body}")
    check(jammed.state()["mode"] != "TRACK", "nothing changed")
    jammed.stop()
finally:
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("front_door"))

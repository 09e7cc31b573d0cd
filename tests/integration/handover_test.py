#!/usr/bin/env python3
"""The hand-over between the console and PC programs against a real `azeltrack serve`
(docs/daemon.md "Who controls the antenna"): after a STOP from the console every protocol still
answers its position query (rotctld `p`, and GS-232B, EasyComm II and SPID through Hamlib's own
rotctl on the daemon's pseudo-terminals) and refuses motion in its own form, nothing moving;
"Allow PC control" (POST /api/control/pc) moves nothing, names the holder in /api/state
`control`, and then a program's position is taken and driven.
Usage: handover_test.py AZELTRACK"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, free_port, http_json, rotctld, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-handover-")
check = Checks()
# Hamlib's models for the daemon's serial protocols, with their rotctl options.
SERIAL = {"gs232b": ["-m", "603"], "easycomm2": ["-m", "202"], "spid": ["-m", "901", "-s", "600"]}


def config(path, web_port, rot_port):
    text = station_toml(web_port, rot_port, mount_rate_deg_s=20.0)
    for protocol in SERIAL:
        baud = "baud = 600\n" if protocol == "spid" else ""
        text += (f'[[serial]]\nprotocol = "{protocol}"\ndevice = "pty:{TMP}/pty/{protocol}"\n'
                 f"{baud}")
    with open(path, "w") as f:
        f.write(text)


def rotctl(protocol, *command):
    r = subprocess.run(["rotctl", *SERIAL[protocol], "-r", f"{TMP}/pty/{protocol}", *command],
                       capture_output=True, text=True, timeout=20)
    return r.returncode, (r.stdout + r.stderr).strip()


def position_of(text):
    """The first two numbers of a `p` answer, or None."""
    try:
        az, el = (float(w) for w in text.split()[:2])
        return az, el
    except ValueError:
        return None


def near(a, b, tol):
    return a is not None and b is not None and abs(((a[0] - b[0] + 180) % 360) - 180) <= tol \
        and abs(a[1] - b[1]) <= tol


web, rot = free_port(), free_port()
base = f"http://127.0.0.1:{web}"
path = os.path.join(TMP, "station.toml")
config(path, web, rot)
token = subprocess.run([BIN, "web", "token", "--config", path], check=True,
                       capture_output=True).stdout.decode().strip()
log = open(os.path.join(TMP, "daemon.log"), "w")
proc = subprocess.Popen([BIN, "serve", "--config", path], stdout=log, stderr=log)


def state():
    return http_json(base, "GET", "/api/state")[1]


def antenna():
    a = state()["antenna"]
    return (a["az_deg"], a["el_deg"]) if a["known"] else None


def still(window_s=0.6):
    """Not moving, and the same reading (within half a 12-bit count) across window_s."""
    before = antenna()
    time.sleep(window_s)
    return not state()["antenna"]["moving"] and near(antenna(), before, 0.04)


try:
    check(wait_until(lambda: antenna() is not None, 15), "started")
    check(rotctld(rot, ["P 100 20"])[0] == "RPRT 0", "a program's position is taken")
    check(wait_until(lambda: near(antenna(), (100, 20), 0.3), 30), "and reached")

    code, _ = http_json(base, "POST", "/api/stop", {})
    control = state()["control"]
    check(code == 200 and state()["pc_locked_out"] and control["holder"] == "console" and
          not control["pc_allowed"], f"console STOP: programs locked out ({control})")
    # "moving" ends with the drive's duty; the simulated motor then coasts for a few of its
    # time constants (axis_plant.hpp), so the stop has settled once two readings agree.
    check(wait_until(still, 15), "the stop settles")
    here = antenna()
    reply = rotctld(rot, ["p", "P 150 30"])
    check(near(position_of(reply[0]), here, 0.2), f"rotctld p answered after STOP: {reply[0]}")
    check(reply[1] == "RPRT -9", f"rotctld P refused as not now (RIG_ERJCTED): {reply[1]}")
    for protocol in SERIAL:
        rc, out = rotctl(protocol, "p")
        check(rc == 0 and near(position_of(out), here, 1.0),
              f"{protocol}: position answered after STOP: rc {rc}, {out!r}")
        rc, out = rotctl(protocol, "P", "150", "30")
        refused = [e["text"] for e in state()["events"] if f"{protocol}" in e["text"] and
                   "refused" in e["text"]]
        check(refused and "locked out" in refused[0],
              f"{protocol}: motion refused, in the record: rc {rc}, {out!r}, {refused[:1]}")
    # Within one step of the simulated 12-bit encoders (0.09°): a reading may flip a count.
    time.sleep(1.0)
    check(near(antenna(), here, 0.1) and state()["mode"] == "STOP",
          f"nothing moved: {here} -> {antenna()}, {state()['mode']}")

    code, body = http_json(base, "POST", "/api/control/pc", {}, token)
    check(code == 200 and body.get("mode") == "EXT", f"Allow PC control: {code} {body}")
    time.sleep(1.5)
    s = state()
    check(near(antenna(), here, 0.1) and not s["pc_locked_out"] and
          s["control"]["pc_allowed"] and s["control"]["holder"] == "console" and
          s["control"]["since"] is not None,
          f"nothing moved; programs allowed; the console holds it: {s['control']}")
    check(rotctld(rot, ["P 130 25"])[0] == "RPRT 0", "then a program's position is taken")
    check(wait_until(lambda: near(antenna(), (130, 25), 0.3), 30), "and driven to")
    check(state()["control"]["holder"] == "pc", "the program holds the antenna")
    code, _ = http_json(base, "POST", "/api/control/pc", {}, None)
    check(code == 401, f"Allow PC control needs a login: {code}")
finally:
    proc.terminate()
    proc.wait(10)
    log.close()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("handover"))

#!/usr/bin/env python3
"""WSJT-X itself beside azeltrack (docs/radio.md "WSJT-X's UDP messages"): Debian's wsjtx started
under Xvfb with its UDP server pointed at the daemon's [wsjtx] listen. Opt-in, run by
scripts/test-wsjtx, not by the test command: it needs WSJT-X and Xvfb, which no other test does,
and waits for WSJT-X's second heartbeat (15 s after the first).

WSJT-X reads its settings from $HOME/.config/WSJT-X.ini (Qt's INI format; group [Configuration],
keys UDPServer and UDPServerPort as WSJT-X's Configuration.cpp reads them, MyCall and MyGrid), so
it runs with a HOME of its own in a temporary folder.

 1  its first heartbeat and its Status messages are decoded (the state's wsjtx.received), from
    id "WSJT-X", with the Status's T/R period read (Q65's: the Status read to its later fields)
 2  a second heartbeat, NetworkMessage.hpp's 15 s pulse later
 3  none of its datagrams counted malformed, and the daemon runs on
 4  WSJT-X restarted in FT8, whose Status says the T/R period is "not applicable": the period is
    FT8's fixed 15 s (docs/radio.md "The T/R period")

Prints how long each took. Exits 77 (skipped) when wsjtx or xvfb-run is not installed.

Usage: wsjtx_xvfb_test.py AZELTRACK"""
import atexit
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, free_port, http_json, station_toml, wait_until

if not shutil.which("wsjtx") or not shutil.which("xvfb-run"):
    print("wsjtx_xvfb: skipped: wsjtx or xvfb-run is not installed (scripts/test-wsjtx installs "
          "them)")
    sys.exit(77)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-wsjtx-")
check = Checks()
procs = []


def stop(p):
    """Stops a process and, when it leads its own session, everything it started (xvfb-run's
    Xvfb, WSJT-X's jt9)."""
    if p.poll() is not None:
        return
    try:
        os.killpg(p.pid, signal.SIGTERM)
    except OSError:
        p.terminate()
    try:
        p.wait(10)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait(5)


def cleanup():
    for p in reversed(procs):
        stop(p)
    shutil.rmtree(TMP, ignore_errors=True)


atexit.register(cleanup)

WEB = free_port()
UDP = free_port()
BASE = f"http://127.0.0.1:{WEB}"
config = os.path.join(TMP, "azeltrack.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=WEB))
    f.write(f'[wsjtx]\nlisten = "127.0.0.1:{UDP}"\n')
log_path = os.path.join(TMP, "daemon.log")
with open(log_path, "w", encoding="utf-8") as log:
    daemon = subprocess.Popen([BIN, "serve", "--config", config], stdout=log,
                              stderr=subprocess.STDOUT, start_new_session=True)
procs.append(daemon)
if not wait_until(lambda: http_json(BASE, "GET", "/api/state")[0] == 200, 20):
    sys.exit("the daemon did not start")

home = os.path.join(TMP, "home")
os.makedirs(os.path.join(home, ".config"))
runtime = os.path.join(TMP, "run")
os.makedirs(runtime, mode=0o700)
env = {k: v for k, v in os.environ.items() if not k.startswith(("XDG_", "DISPLAY", "QT_"))}
env.update(HOME=home, XDG_RUNTIME_DIR=runtime)
wsjtx_log = open(os.path.join(TMP, "wsjtx.log"), "w", encoding="utf-8")


def start_wsjtx(mode):
    """WSJT-X under Xvfb in `mode`, sending to the daemon; the process."""
    with open(os.path.join(home, ".config", "WSJT-X.ini"), "w", encoding="utf-8") as ini:
        ini.write(f"[Configuration]\nMyCall=W1AW\nMyGrid=FN31PR\nUDPServer=127.0.0.1\n"
                  f"UDPServerPort={UDP}\n[Common]\nMode={mode}\n")
    p = subprocess.Popen(["xvfb-run", "-a", "wsjtx"], env=env, stdout=wsjtx_log,
                         stderr=subprocess.STDOUT, start_new_session=True)
    procs.append(p)
    return p


# Q65, an EME mode whose T/R period WSJT-X puts in its Status (for FT8's fixed 15 s it sends the
# "not applicable" quint32 maximum, mainwindow.cpp statusUpdate).
started = time.monotonic()
q65 = start_wsjtx("Q65")


def wsjtx():
    return http_json(BASE, "GET", "/api/state")[1]["wsjtx"]


def seconds_until(condition, limit_s):
    """Seconds from WSJT-X's start until `condition(state.wsjtx)`, or None after `limit_s`."""
    if wait_until(lambda: condition(wsjtx()), limit_s - (time.monotonic() - started), 0.05):
        return time.monotonic() - started
    return None


def seconds(s):
    return "never" if s is None else f"{s:.1f} s"


first_heartbeat = seconds_until(lambda w: w["received"]["heartbeat"] >= 1, 30)
first_status = seconds_until(lambda w: w["received"]["status"] >= 1, 30)
second_heartbeat = seconds_until(lambda w: w["received"]["heartbeat"] >= 2, 50)
state = wsjtx()
print(f"WSJT-X under Xvfb: first heartbeat {seconds(first_heartbeat)}, first Status "
      f"{seconds(first_status)}, second heartbeat {seconds(second_heartbeat)} after its start; "
      f"received {state['received']}, "
      f"malformed {state['malformed']}, T/R period {state['tr_period_s']} s")
if first_heartbeat is None:
    print(open(os.path.join(TMP, "wsjtx.log"), encoding="utf-8").read(), file=sys.stderr)
check(first_heartbeat is not None, "1: WSJT-X's first heartbeat decoded")
check(first_status is not None, "1: a Status decoded")
check(state["id"] == "WSJT-X", f"1: from WSJT-X: {state['id']!r}")
check(isinstance(state["tr_period_s"], (int, float)) and state["tr_period_s"] > 0,
      f"1: the Status's T/R period: {state['tr_period_s']}")
check(second_heartbeat is not None and first_heartbeat is not None and
      13.0 <= second_heartbeat - first_heartbeat <= 17.0,
      f"2: the next heartbeat 15 s later: {first_heartbeat} -> {second_heartbeat}")
check(state["malformed"] == 0, f"3: none malformed: {state['last_malformed']}")
check(daemon.poll() is None, "3: the daemon runs on")
check("malformed" not in open(log_path, encoding="utf-8").read(), "3: no malformed line in the log")

print(f"took {time.monotonic() - started:.1f} s with WSJT-X in Q65")

# 4: FT8, whose Status leaves the period out.
stop(q65)
statuses = wsjtx()["received"]["status"]
started = time.monotonic()
start_wsjtx("FT8")
ft8_status = seconds_until(lambda w: w["received"]["status"] > statuses, 30)
state = wsjtx()
print(f"WSJT-X in FT8: a Status {seconds(ft8_status)} after its start, T/R period "
      f"{state['tr_period_s']} s, malformed {state['malformed']}")
check(ft8_status is not None and state["tr_period_s"] == 15, f"4: FT8's 15 s: {state}")
check(state["malformed"] == 0, f"4: none malformed: {state['last_malformed']}")
print(f"took {time.monotonic() - started:.1f} s with WSJT-X in FT8")
sys.exit(check.summary("wsjtx_xvfb"))

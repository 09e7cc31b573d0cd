#!/usr/bin/env python3
"""A pointing scan (docs/calibration.md) run by `azeltrack serve` on its simulated antenna. This
test is the receiver: it reads where the antenna points (/api/state) and sends the power a 2°
Gaussian beam would see from a source that sits 0.4° of azimuth and −0.25° of elevation away from
where the ephemeris puts it, as dB lines over UDP ([receiver] udp). The scan must find that offset,
and its one-press apply must put it into [corrections] (saved). Refusals: no readings, a bad plan, a
STOP mid-scan. Usage: scan_test.py AZELTRACK"""
import fcntl
import math
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

from daemon_harness import (FIXED_UTC, START_NEAR_SCAN_SOURCE, Checks, cross_scan_of_a_source,
                            free_port, http_json, station_toml, wait_until)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-scan-")
check = Checks()
TRUE_AZ, TRUE_EL, BEAM = 0.4, -0.25, 2.0

web, udp_port = free_port(), free_port()
config = os.path.join(TMP, "scan.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=web, mount_rate_deg_s=4.0) + START_NEAR_SCAN_SOURCE)
    f.write(f'[receiver]\nsource = "udp"\nport = {udp_port}\nstale_s = 2.0\n')
token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                       capture_output=True).stdout.decode().strip()
base = f"http://127.0.0.1:{web}"
log = open(os.path.join(TMP, "serve.log"), "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", FIXED_UTC], stdout=log,
                          stderr=subprocess.STDOUT)
feeding = threading.Event()
done = threading.Event()


def state():
    return http_json(base, "GET", "/api/state")[1]


def power_db(s):
    """What the beam sees of the displaced source. The beam is where the encoders read (this
    mount's encoders are true); the readings the controller uses add the offsets applied."""
    ant, tgt = s["antenna"], s.get("target") or {}
    if not ant.get("known") or "az_deg" not in tgt or tgt.get("az_deg") is None:
        return 0.0
    src_az, src_el = tgt["az_deg"] + TRUE_AZ, tgt["el_deg"] + TRUE_EL
    d_az = (ant["encoder_az_deg"] - src_az + 180.0) % 360.0 - 180.0
    d2 = (d_az * math.cos(math.radians(src_el))) ** 2 + (ant["encoder_el_deg"] - src_el) ** 2
    return 10.0 * math.log10(1.0 + 3.0 * math.exp(-4.0 * math.log(2.0) * d2 / BEAM ** 2))


def feeder():
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    while not done.is_set():
        if feeding.is_set():
            try:
                sock.sendto(f"{power_db(state()):.4f} dB\n".encode(), ("127.0.0.1", udp_port))
            except OSError:
                pass
        time.sleep(0.2)


try:
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start: " + open(log.name, encoding="utf-8").read())
    threading.Thread(target=feeder, daemon=True).start()
    scan, source_el_deg = cross_scan_of_a_source(base, BEAM)
    source = scan["source"]

    code, body = http_json(base, "POST", "/api/scan", scan, token)
    check(code == 503 and "silent" in body.get("error", str(body)), f"no readings: refused {code} {body}")
    check(state()["mode"] == "STOP", "a refused scan moves nothing")
    code, body = http_json(base, "POST", "/api/scan", dict(scan, beamwidth_deg=0), token)
    check(code == 400 and body.get("field") == "beamwidth_deg", f"a bad beam: {code} {body}")
    code, body = http_json(base, "POST", "/api/scan/apply", {}, token)
    check(code == 409, f"nothing to apply yet: {code} {body}")

    feeding.set()
    check(wait_until(lambda: state()["receiver"]["state"] == "receiving", 5), "readings flow")
    # A scan stopped by the operator's STOP.
    code, body = http_json(base, "POST", "/api/scan", scan, token)
    check(code == 200 and body["scan"]["state"] == "running", f"started: {code} {body}")
    http_json(base, "POST", "/api/stop", {}, token)
    check(wait_until(lambda: state()["scan"]["state"] == "stopped", 5), f"STOP ends it: {state()['scan']}")

    code, body = http_json(base, "POST", "/api/scan", scan, token)
    check(code == 200 and body["mode"] == "TRACK", f"tracks {source} and scans: {code} {body}")
    t0 = time.monotonic()
    finished = wait_until(lambda: state()["scan"]["state"] != "running", 240, 0.5)
    s = state()["scan"]
    print(f"scan of {source}: {s['state']} after {time.monotonic() - t0:.0f} s, "
          f"{s.get('points_done')}/{s.get('points_total')} points, found {s.get('found')}, "
          f"fit {s.get('fit')}, {s.get('reason')}")
    check(finished and s["state"] == "done", f"the scan ends fitted: {s}")
    check(len(s.get("samples", [])) == 20 and all(x["power_db"] is not None for x in s["samples"]),
          "every point read")
    found = s.get("found", {})
    check(abs(found.get("az_offset_deg", 9) - TRUE_AZ) < 0.06 and
          abs(found.get("el_offset_deg", 9) - TRUE_EL) < 0.06, f"the source's offset found: {found}")
    check(abs(s["fit"]["width_xel_deg"] - BEAM) < 0.2, f"the beam's width: {s['fit']}")

    # docs/reliability.md "Hardening, round three" row 8: an apply refused while another program
    # holds the settings file (503 after the daemon's 5 s wait) keeps the result for the next apply.
    lock_fd = os.open(config + ".lock", os.O_RDWR | os.O_CREAT, 0o600)
    fcntl.flock(lock_fd, fcntl.LOCK_EX)
    try:
        code, body = http_json(base, "POST", "/api/scan/apply", {}, token, timeout=15)
    finally:
        fcntl.flock(lock_fd, fcntl.LOCK_UN)
        os.close(lock_fd)
    check(code == 503, f"an apply while the file is held: 503: {code} {body}")
    check(state()["scan"].get("found") == found, f"the result is kept: {state()['scan'].get('found')}")
    # docs/reliability.md "Hardening, round three" row 9: an offset another program set meanwhile is
    # what the found one comes off.
    subprocess.run([BIN, "config", "set", "--config", config, "corrections.az_offset_deg", "1.0"],
                   check=True, stdout=subprocess.DEVNULL)
    code, body = http_json(base, "POST", "/api/scan/apply", {}, token, timeout=15)
    check(code == 200, f"applied: {code} {body}")
    text = open(config, encoding="utf-8").read()
    saved = {k: float(v) for k, v in (line.split(" = ") for line in text.splitlines()
                                      if line.startswith(("az_offset_deg", "el_offset_deg")))}
    check(abs(saved.get("az_offset_deg", 9) - (1.0 - found["az_offset_deg"])) < 1e-9 and
          abs(saved.get("el_offset_deg", 9) + found["el_offset_deg"]) < 1e-9,
          f"the found offsets taken off the file's (az 1.0 set by `config set`): {saved}")
    code, _ = http_json(base, "POST", "/api/scan/apply", {}, token)
    check(code == 409, "applied once, not twice")
    # The offset as if nobody had set 1.0, for the pointing check below.
    code, body = http_json(base, "PUT", "/api/config/offsets",
                           {"az_offset_deg": -found["az_offset_deg"]}, token)
    check(code == 200, f"the az offset set back: {code} {body}")
    # The antenna now reads where the beam is: the source's true place is the target.
    check(wait_until(lambda: power_db(state()) > 5.85, 30),
          f"on the source after the apply: {power_db(state()):.2f} dB of 6.02")
    daemon.send_signal(signal.SIGTERM)
    check(daemon.wait(10) == 0, "exits cleanly")
finally:
    done.set()
    if daemon.poll() is None:
        daemon.kill()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("scan"))

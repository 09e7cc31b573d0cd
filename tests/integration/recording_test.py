#!/usr/bin/env python3
"""Recording from the API (docs/calibration.md "Recording") on `azeltrack serve`'s simulated
antenna with the simulated receiver: POST /api/recording at 10 Hz while the station tracks Cas A,
a few seconds, POST /api/recording/stop; the CSV under recordings/ in the state directory holds
rate × time rows, every column parses, the demand is the station's target as /api/state showed
it at those moments, the power is the receiver's; GET /api/recordings lists it with its rows and
bytes, GET /api/recordings/NAME downloads it, and a name that is not a recording's (a path) is
404. A bad rate is refused naming rate_hz, a second start is 409. GET /api/noise/log reads the
noise log newest first. About 7 s. Usage: recording_test.py AZELTRACK"""
import csv
import io
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from datetime import datetime

from daemon_harness import FIXED_UTC, Checks, free_port, http_json, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-rec-")
check = Checks()

web = free_port()
config = os.path.join(TMP, "rec.toml")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=web, mount_rate_deg_s=8.0))
    f.write('[receiver]\nsource = "sim"\n')
    f.write("[sim.receiver]\nbeamwidth_deg = 2.0\ndish_m = 25.0\nnoise_db = 0.05\n")
    f.write("[sim.az]\nstart_deg = 310.0\n[sim.el]\nstart_deg = 57.0\n")
# Two measurements logged earlier (and one torn line): the log reads newest first.
with open(os.path.join(TMP, "noise-log.jsonl"), "w", encoding="utf-8") as f:
    f.write('{"utc":"2025-11-01T12:00:00.000Z","source":"Sun","y_factor_db":12.1}\n{torn\n'
            '{"utc":"2025-11-02T12:00:00.000Z","source":"Sun","y_factor_db":12.4}\n')
token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                       capture_output=True).stdout.decode().strip()
base = f"http://127.0.0.1:{web}"
log = open(os.path.join(TMP, "serve.log"), "w", encoding="utf-8")
daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", FIXED_UTC], stdout=log,
                          stderr=subprocess.STDOUT)


def state():
    return http_json(base, "GET", "/api/state")[1]


def get_raw(route):
    """(status, content type, disposition, text) of a GET."""
    try:
        with urllib.request.urlopen(base + route, timeout=5) as r:
            return (r.status, r.headers.get("Content-Type"), r.headers.get("Content-Disposition"),
                    r.read().decode())
    except urllib.error.HTTPError as e:
        return e.code, e.headers.get("Content-Type"), None, e.read().decode()


def unix(utc):
    return datetime.fromisoformat(utc.replace("Z", "+00:00")).timestamp()


try:
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start: " + open(log.name, encoding="utf-8").read())
    check(state()["recording"]["state"] == "idle", "no recording at the start")
    code, body = http_json(base, "GET", "/api/noise/log")
    entries = body.get("entries", []) if code == 200 else []
    check(code == 200 and [e.get("y_factor_db") for e in entries] == [12.4, 12.1]
          and body.get("bad_lines") == 1, f"the noise log, newest first: {code} {body}")
    check(http_json(base, "POST", "/api/target", {"name": "casa"}, token)[0] == 200, "track Cas A")
    check(wait_until(lambda: state()["receiver"]["state"] == "receiving", 5), "the receiver reads")

    code, body = http_json(base, "POST", "/api/recording", {"rate_hz": 60}, token)
    check(code == 400 and body.get("field") == "rate_hz", f"60 Hz refused naming it: {code} {body}")
    code, body = http_json(base, "POST", "/api/recording", {"rate_hz": 10}, token)
    t0 = time.monotonic()
    rec = body.get("recording", {})
    check(code == 200 and rec.get("state") == "recording" and rec.get("rate_hz") == 10,
          f"recording at 10 Hz: {code} {body}")
    check(http_json(base, "POST", "/api/recording", {"rate_hz": 1}, token)[0] == 409,
          "a second start is 409 while one runs")
    seen = []  # (utc, target az, el) as /api/state showed them
    while time.monotonic() - t0 < 4.0:
        s = state()
        if s["target"]["az_deg"] is not None:
            seen.append((unix(s["utc"]), s["target"]["az_deg"], s["target"]["el_deg"]))
        time.sleep(0.3)
    code, body = http_json(base, "POST", "/api/recording/stop", {}, token)
    elapsed = time.monotonic() - t0
    rec = body.get("recording", {})
    name = rec.get("file", "")
    print(f"recorded {rec.get('rows')} rows in {elapsed:.2f} s to {name} ({rec.get('bytes')} bytes)")
    check(code == 200 and rec.get("state") == "stopped", f"stopped: {code} {body}")
    check(abs(rec.get("rows", 0) - 10 * elapsed) <= 3, f"rows ≈ 10 Hz × {elapsed:.2f} s: {rec}")

    path = os.path.join(TMP, "recordings", name)
    check(wait_until(lambda: os.path.exists(path) and
                     open(path, encoding="utf-8").read().count("\n") == rec.get("rows", -9) + 1, 5),
          "every row reaches the file under recordings/")
    code, body = http_json(base, "GET", "/api/recordings")
    listed = body.get("recordings", []) if code == 200 else []
    check(len(listed) == 1 and listed[0].get("name") == name and listed[0].get("rows") == rec["rows"]
          and listed[0].get("bytes") == os.path.getsize(path), f"listed: {code} {body}")

    code, ctype, disposition, text = get_raw("/api/recordings/" + name)
    check(code == 200 and ctype == "text/csv" and name in (disposition or ""),
          f"downloaded as CSV: {code} {ctype} {disposition}")
    rows = list(csv.DictReader(io.StringIO(text)))
    check(len(rows) == rec["rows"], f"{len(rows)} rows downloaded")
    header = text.splitlines()[0].split(",") if text else []
    check(header == ["utc", "demand_az_deg", "demand_el_deg", "reading_az_deg", "reading_el_deg",
                     "error_az_deg", "error_el_deg", "power_db", "mode"], f"header {header}")
    parsed = []
    try:
        for r in rows:
            parsed.append({k: (r[k] if k == "mode" else unix(r[k]) if k == "utc" else float(r[k]))
                           for k in header})
    except (ValueError, KeyError) as e:
        check(False, f"a column does not parse: {e}")
    check(len(parsed) == len(rows) and all(p["mode"] == "TRACK" for p in parsed),
          "every column parses, every row TRACK")
    if len(parsed) > 2:
        steps = sorted(b["utc"] - a["utc"] for a, b in zip(parsed, parsed[1:]))
        median = steps[len(steps) // 2]
        check(abs(median - 0.1) < 0.01, f"rows 0.1 s apart (median {median:.3f} s)")
        worst = 0.0
        for utc, az, el in seen:
            near = min(parsed, key=lambda p: abs(p["utc"] - utc))
            if abs(near["utc"] - utc) < 0.1:
                worst = max(worst, abs(near["demand_az_deg"] - az), abs(near["demand_el_deg"] - el))
        print(f"demand against the target shown: {len(seen)} moments, worst {worst:.4f}°")
        check(len(seen) >= 5 and worst < 0.02, f"the demand follows the target: worst {worst}°")
        errors = [abs(p["error_az_deg"] - (p["demand_az_deg"] - p["reading_az_deg"])) for p in parsed]
        check(max(errors) < 1e-4, "error = demand − reading")
        check(len({round(p["power_db"], 3) for p in parsed}) > 1, "the receiver's power, read")

    for bad in ["/api/recordings/..%2Frec.toml", "/api/recordings/rec.toml",
                "/api/recordings/recording-20251120T040000Z.csv%00", "/api/recordings/%2e%2e"]:
        code, _, _, text = get_raw(bad)
        check(code == 404 and "[web]" not in text, f"{bad} is 404: {code}")
    daemon.send_signal(signal.SIGTERM)
    check(daemon.wait(10) == 0, "exits cleanly")
finally:
    if daemon.poll() is None:
        daemon.kill()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("recording"))

#!/usr/bin/env python3
"""The pointing calibration session in the daemon (docs/calibration.md "In the daemon") on
`azeltrack serve`'s simulated antenna and receiver, in real time. A session of three Sun scans runs
from the API and each result lands in scan-log.csv beside the configuration; a restart mid-session
loses no row and resumes; then, on a fresh log: a fit with too few scans is refused with the
reason, a bad CSV is refused naming line and column with nothing appended, an imported CSV of 60
offsets generated here from known terms (the model's exact geometry, ported below) fits those terms
within 0.005°, apply saves them as [pointing] and restore brings the previous model back (read back
from the file and /api/state). The Sun at FN06HE at 17:00 UTC on 2025-11-20 is at az 181°, el 26°;
the antenna starts beside it. About 140 s (each five-point scan takes some 40 s of the simulated
mount's real-time moves and settling). Usage: calibration_session_test.py AZELTRACK"""
import csv
import datetime
import io
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, free_port, http_json, http_upload, station_toml, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-calsession-")
check = Checks()
START = datetime.datetime(2025, 11, 20, 17, 0, 0, tzinfo=datetime.timezone.utc)
TERMS = {"ia_deg": 0.3, "ie_deg": -0.2, "ca_deg": 0.15, "npae_deg": 0.1, "an_deg": 0.05,
         "aw_deg": -0.08, "sag_deg": 0.12}
KEYS = list(TERMS)

web = free_port()
config = os.path.join(TMP, "station.toml")
scan_log = os.path.join(TMP, "scan-log.csv")
session_file = os.path.join(TMP, "calibration-session.json")
with open(config, "w", encoding="utf-8") as f:
    f.write(station_toml(web_port=web, mount_rate_deg_s=8.0).replace(
        '[station]\n', '[station]\ndish_m = 3.0\nefficiency = 0.6\n'))
    f.write('[sky]\nband = "1296"\n[receiver]\nsource = "sim"\ntsys_k = 100.0\n')
    f.write("[sim.receiver]\nbeamwidth_deg = 2.0\nnoise_db = 0.05\n")
    f.write("[sim.az]\nstart_deg = 181.0\n[sim.el]\nstart_deg = 26.0\n")
token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                       capture_output=True).stdout.decode().strip()
base = f"http://127.0.0.1:{web}"
SESSION = {"sources": ["sun"], "hours": 1, "kind": "five-point", "sun_every_min": 0.2,
           "beamwidth_deg": 2.0, "settle_s": 0.3, "dwell_s": 0.6, "refine": False, "max_scans": 3}
daemon = None
log = open(os.path.join(TMP, "serve.log"), "a", encoding="utf-8")


def serve(utc):
    global daemon
    daemon = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start",
                               utc.strftime("%Y-%m-%dT%H:%M:%SZ")], stdout=log,
                              stderr=subprocess.STDOUT)
    if not wait_until(lambda: http_json(base, "GET", "/api/state")[0] == 200, 20):
        sys.exit("the daemon did not start: " + open(log.name, encoding="utf-8").read())
    check(wait_until(lambda: state()["receiver"]["state"] == "receiving", 5), "the receiver reads")


def stop_daemon():
    daemon.send_signal(signal.SIGTERM)
    check(daemon.wait(10) == 0, "exits cleanly")


def state():
    return http_json(base, "GET", "/api/state")[1]


def config_get(key):
    out = subprocess.run([BIN, "config", "get", "--config", config, key], capture_output=True,
                         text=True).stdout.strip()
    try:
        return float(out)
    except ValueError:
        return float("nan")


def file_rows(path):
    if not os.path.exists(path):
        return []
    lines = [line for line in open(path, encoding="utf-8") if line.strip()]
    return list(csv.DictReader(lines))


# The pointing model's exact geometry (core/src/calibration/pointing_model.cpp), for the offsets a
# mount with TERMS shows: the mount angles that put the beam on a source.
def rad(d):
    return math.radians(d)


def beam_on_sky(az, el, t):
    alpha, eps = rad(az - t["ia_deg"]), el - t["ie_deg"]
    eps = rad(eps - t["sag_deg"] * math.cos(rad(eps)))
    fwd = (math.sin(alpha), math.cos(alpha), 0.0)
    right = (math.cos(alpha), -math.sin(alpha), 0.0)
    n, c = rad(t["npae_deg"]), rad(t["ca_deg"])
    axis = tuple(math.cos(n) * r + math.sin(n) * u for r, u in zip(right, (0.0, 0.0, 1.0)))
    raised = cross(axis, fwd)
    v = tuple(math.cos(c) * (math.cos(eps) * a + math.sin(eps) * b) + math.sin(c) * k
              for a, b, k in zip(fwd, raised, axis))
    north, east = rad(t["an_deg"]), rad(t["aw_deg"])
    angle = math.hypot(north, east)
    if angle:
        toward = (east / angle, north / angle, 0.0)
        k = cross((0.0, 0.0, 1.0), toward)
        kv = cross(k, v)
        d = sum(a * b for a, b in zip(k, v))
        v = tuple(math.cos(angle) * a + math.sin(angle) * b + (1 - math.cos(angle)) * d * kk
                  for a, b, kk in zip(v, kv, k))
    return (math.degrees(math.atan2(v[0], v[1])) % 360.0,
            math.degrees(math.atan2(v[2], math.hypot(v[0], v[1]))))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def mount_for_sky(az, el, t):
    m_az, m_el = az, el
    for _ in range(60):
        b_az, b_el = beam_on_sky(m_az, m_el, t)
        d_az, d_el = (az - b_az + 180.0) % 360.0 - 180.0, el - b_el
        m_az, m_el = m_az + d_az, m_el + d_el
        if abs(d_az) < 1e-11 and abs(d_el) < 1e-11:
            break
    return m_az, m_el


def generated_csv():
    """60 sources spread over azimuth and 15–75° of elevation (a golden-ratio walk), their mount
    offsets from TERMS, in other tools' columns."""
    out = io.StringIO()
    out.write("utc,az,el,daz,del,weight,source\n")
    for i in range(60):
        az = (i * 137.508) % 360.0
        el = 15.0 + 60.0 * ((i * 0.618034) % 1.0)
        m_az, m_el = mount_for_sky(az, el, TERMS)
        utc = (START - datetime.timedelta(days=1) + datetime.timedelta(minutes=10 * i))
        out.write(f"{utc.strftime('%Y-%m-%dT%H:%M:%SZ')},{az:.6f},{el:.6f},"
                  f"{(m_az - az + 180.0) % 360.0 - 180.0:.7f},{m_el - el:.7f},1,star{i}\n")
    return out.getvalue()


t0 = time.monotonic()
try:
    serve(START)
    code, body = http_json(base, "GET", "/api/calibration/sources")
    sun = [s for s in body.get("sources", []) if s["name"].lower() == "sun"]
    check(code == 200 and body.get("given") is True and sun and sun[0]["worth"] and
          sun[0]["snr_db"] > 10, f"the Sun is worth scanning with the dish given: {code} {sun}")
    code, body = http_json(base, "POST", "/api/calibration/session", dict(SESSION, hours=-1), token)
    check(code == 400 and body.get("field") == "hours", f"a bad hours named: {code} {body}")
    code, body = http_json(base, "POST", "/api/calibration/session", dict(SESSION, kind="zigzag"),
                           token)
    check(code == 400 and body.get("field") == "kind", f"a bad kind named: {code} {body}")
    code, body = http_json(base, "POST", "/api/calibration/session", dict(SESSION, sources=["x1"]),
                           token)
    check(code == 400 and body.get("field") == "sources", f"an unknown source named: {code} {body}")
    check(state()["mode"] == "STOP", "nothing moved on a refusal")

    code, body = http_json(base, "POST", "/api/calibration/session", SESSION, token)
    check(code == 200 and body["calibration"]["state"] == "running", f"started: {code} {body}")
    check(body["calibration"]["scans_planned"] == 3, f"three scans planned: {body}")
    code, body = http_json(base, "POST", "/api/scan", {"source": "sun", "beamwidth_deg": 2.0}, token)
    check(code == 409, f"no single scan during a session: {code} {body}")
    check(wait_until(lambda: os.path.exists(session_file), 5), "the session's request is kept")
    check(wait_until(lambda: state()["calibration"]["log_rows"] >= 1, 60, 0.5),
          f"the first scan lands in the log: {state()['calibration']}")
    s = state()["calibration"]
    row = s["last_rows"][-1] if s["last_rows"] else {}
    check(len(file_rows(scan_log)) == 1, f"and in scan-log.csv: {file_rows(scan_log)}")
    # The simulated encoders have 12 bits (0.088°): the mount's offsets read within a step.
    check(row.get("source") == "Sun" and abs(row.get("daz_deg", 9)) < 0.1 and
          abs(row.get("del_deg", 9)) < 0.1, f"on a true mount the Sun is found where it is: {row}")
    # A restart mid-session: the clock carries on from where it was.
    elapsed = time.monotonic() - t0
    stop_daemon()
    rows_before = file_rows(scan_log)
    check(os.path.exists(session_file), "the session's request outlives the daemon")
    serve(START + datetime.timedelta(seconds=elapsed + 2))
    s = state()["calibration"]
    check(s["state"] == "running" and s["log_rows"] == len(rows_before) and
          s["scans_done"] == len(rows_before), f"resumed with its rows: {s}")
    check(wait_until(lambda: state()["calibration"]["state"] != "running", 90, 0.5),
          "the session ends")
    s = state()["calibration"]
    rows = file_rows(scan_log)
    print(f"session: {s['state']} ({s['reason']}), {s['scans_done']} scans, rows {len(rows)} at "
          f"{[r['utc'] for r in rows]}, after {time.monotonic() - t0:.0f} s")
    check(s["state"] == "done" and s["scans_done"] == 3 and len(rows) == 3 and
          rows[:len(rows_before)] == rows_before, f"three scans, none lost: {s} {rows}")
    check(wait_until(lambda: not os.path.exists(session_file), 5), "the request removed at the end")
    code, text = 0, ""
    try:
        import urllib.request
        with urllib.request.urlopen(base + "/api/calibration/log", timeout=5) as r:
            code, text, ctype = r.status, r.read().decode(), r.headers.get("Content-Type", "")
    except OSError as e:
        ctype = str(e)
    check(code == 200 and ctype.startswith("text/csv") and len(text.strip().splitlines()) == 4,
          f"the export: {code} {ctype} {text[:200]}")
    stop_daemon()

    # A fresh log for the fit (the rows above hold the simulated mount's own, true, pointing).
    shutil.move(scan_log, scan_log + ".session")
    serve(START + datetime.timedelta(minutes=30))
    code, body = http_json(base, "GET", "/api/calibration/fit")
    check(code == 409 and "too few scans" in body.get("refused", ""), f"too few: {code} {body}")
    code, body = http_upload(base, "/api/calibration/log",
                             b"utc,az,el,daz,del\n2025-11-19T10:00:00Z,10,20,0.1,0.1\n"
                             b"2025-11-19T10:01:00Z,10,north,0.1,0.1\n", token, "text/csv")
    check(code == 400 and "line 3" in body.get("error", "") and body.get("field") in ("el", "el_deg"),
          f"a bad row named by line and column: {code} {body}")
    check(state()["calibration"]["log_rows"] == 0 and not os.path.exists(scan_log),
          "nothing of it appended")
    code, body = http_upload(base, "/api/calibration/log", generated_csv().encode(), token, "text/csv")
    check(code == 200 and body.get("imported") == 60, f"60 rows imported: {code} {body}")
    check(len(file_rows(scan_log)) == 60, "appended to scan-log.csv")
    code, fit = http_json(base, "GET", "/api/calibration/fit")
    errors = {k: abs(fit.get("terms", {}).get(k, 9) - v) for k, v in TERMS.items()}
    print(f"fit of 60 generated offsets: largest term error {max(errors.values()):.6f}°, rms "
          f"{fit.get('rms_before_deg')} -> {fit.get('rms_after_deg')}")
    check(code == 200 and max(errors.values()) < 0.005 and not fit.get("held"),
          f"the known terms fitted within 0.005°: {errors} held {fit.get('held')}")

    code, body = http_json(base, "POST", "/api/calibration/apply", {}, token)
    check(code == 200 and body.get("model", {}).get("why") == "fit", f"applied: {code} {body}")
    saved = {k: config_get(f"pointing.{k}") for k in KEYS}
    check(all(abs(saved[k] - fit["terms"][k]) < 1e-9 for k in KEYS),
          f"[pointing] saved in the file: {saved}")
    model = state()["calibration"]["model"]
    check(all(abs(model[k] - fit["terms"][k]) < 1e-12 for k in KEYS), f"in use: {model}")
    code, body = http_json(base, "GET", "/api/calibration/history")
    models = body.get("models", [])
    check(code == 200 and [m["why"] for m in models] == ["fit", "in use"] and
          all(v == 0 for v in models[-1]["terms"].values()),
          f"the history, newest first, with the model in use before: {body}")
    history_lines = open(os.path.join(TMP, "pointing-history.jsonl"), encoding="utf-8").readlines()
    check(len(history_lines) == 2, f"pointing-history.jsonl: {history_lines}")
    code, body = http_json(base, "POST", "/api/calibration/restore", {"id": 99}, token)
    check(code == 400 and body.get("field") == "id", f"an unknown id named: {code} {body}")
    code, body = http_json(base, "POST", "/api/calibration/restore", {"id": models[-1]["id"]}, token)
    check(code == 200 and body["model"]["why"] == "restore", f"restored: {code} {body}")
    model = state()["calibration"]["model"]
    check(all(model[k] == 0 for k in KEYS), f"the earlier model in use again: {model}")
    saved = {k: config_get(f"pointing.{k}") for k in KEYS}
    check(all(v == 0 for v in saved.values()), f"and in the file: {saved}")
    stop_daemon()
finally:
    if daemon is not None and daemon.poll() is None:
        daemon.kill()
    if check.failed:
        print(open(log.name, encoding="utf-8").read()[-4000:])
    shutil.rmtree(TMP, ignore_errors=True)

print(f"calibration_session: {time.monotonic() - t0:.0f} s")
sys.exit(check.summary("calibration_session"))

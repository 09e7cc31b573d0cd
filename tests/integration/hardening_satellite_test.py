#!/usr/bin/env python3
"""docs/reliability.md "Hardening" against a real `azeltrack serve` on the simulated antenna: a
satellite whose name is not UTF-8, tracked with a live view open and as the target at start. Rows
as the table numbers them; each check was written to fail on the code before the fixes. A failure
prints what was sent and what came back, and the daemon's log; hardening_station.py has the
station, hardening_clients.py the clients.

 2  a satellite catalogue with a Latin-1 name, tracked with a WebSocket open, and at start

Usage: hardening_satellite_test.py AZELTRACK"""
import json
import time

import hardening_station as station
from hardening_clients import read_frames, read_head, request, state, ws_connect
from hardening_station import NORAD, alive, check, config_set, figure, start_daemon, stop_daemon

_, TOKEN = station.prepare()

t_start = time.monotonic()
try:
    if not start_daemon("daemon"):
        raise SystemExit(1)

    # ---- Row 2: a Latin-1 satellite name, tracked, with a live view open --------------------
    r = request("POST", "/api/target", {"name": f"sat:{NORAD}"}, TOKEN)
    check(r.status == 200, f"row 2: track sat:{NORAD}: {r.status} {r.raw[:300]!r}")
    ws = ws_connect()
    status = read_head(ws)
    check(" 101 " in status, f"row 2: WebSocket handshake: {status}")
    frames = read_frames(ws, 1.2)
    texts = [f[1] for f in frames if f[0] == 1]
    states = []
    for t in texts:
        try:
            states.append(json.loads(t.decode("utf-8")))
        except ValueError as e:
            check(False, f"row 2: a pushed frame is not valid JSON: {e} {t[:200]!r}")
    check(len(states) >= 4 and all(str(s["target"]["name"]).startswith("sat:") for s in states),
          f"row 2: frames keep arriving while the satellite is tracked: {len(states)} in 1.2 s, "
          f"targets {[s['target']['name'] for s in states][:3]}")
    targets = request("GET", "/api/targets")
    sats = targets.body.get("satellites", []) if isinstance(targets.body, dict) else []
    check(targets.status == 200 and len(sats) == 1 and sats[0]["name"].startswith("ISS Z") and
          sats[0]["name"].endswith("RYA") and str(sats[0]["norad"]) == NORAD,
          f"row 2: /api/targets answers 200 with valid JSON: {targets.status} "
          f"{targets.raw[:300]!r}")
    more = read_frames(ws, 0.5)  # still pushing after the listing
    ws.close()
    check(len(more) >= 1, f"row 2: frames still arrive after /api/targets: {len(more)}")
    st = state()
    check(st["mode"] == "TRACK" and st["target"]["name"].startswith("sat:"),
          f"row 2: tracking the satellite: {st['mode']} {st['target']}")
    alive(2)
    figure(2, f"tracked {st['target']['name']!r}: {len(states)} frames in 1.2 s (+{len(more)} in "
              f"0.5 s after), /api/targets {targets.status} ({len(targets.raw)} B, name "
              f"{sats[0]['name'] if sats else None!r})")

    # ---- Row 2, at start: the satellite as the configured target ----------------------------
    rc = stop_daemon()
    check(rc == 0, f"row 2: the daemon stops cleanly: {rc}")
    r = config_set("target.name", f'"sat:{NORAD}"')
    check(r.returncode == 0,
          f"row 2: config set target.name sat:{NORAD}: {r.returncode} {r.stderr!r}")
    if start_daemon("restart"):
        st = state()
        check(st["mode"] == "TRACK" and st["target"]["name"].startswith("sat:"),
              f"row 2: started tracking the satellite: {st['mode']} {st['target']}")
        targets = request("GET", "/api/targets")
        check(targets.status == 200 and isinstance(targets.body, dict),
              f"row 2: /api/targets after the restart: {targets.status} {targets.raw[:200]!r}")
        figure(2, f"restart with [target] name = \"sat:{NORAD}\": {st['mode']} "
                  f"{st['target']['name']!r}, /api/targets {targets.status}")
    alive(2)
    stop_daemon()
finally:
    station.stop_all()
station.report(t_start)

#!/usr/bin/env python3
"""docs/reliability.md "Hardening" against a real `azeltrack serve` on the simulated antenna:
requests a client from outside can make: a path and Host headers that are not UTF-8, an
oversized header, slot numbers beyond 32 bits, and a refusal of rotctld's shown to the operator
(§7). Rows as the table numbers them; each check was written to fail on the code before the
fixes. A failure prints what was sent and what came back, and the daemon's log;
hardening_station.py has the station, hardening_clients.py the clients.

 1  a Host header that is not UTF-8 (b"\\xff", Latin-1 b"caf\\xe9"): 403 with a JSON body, alive
 9  slot numbers beyond 32 bits: 400, nothing changes
12  GET /\\xff: 404 with JSON; a 100 KB header: 431

Usage: hardening_requests_test.py AZELTRACK"""
import socket
import time

import hardening_station as station
from hardening_clients import (ROT_PORT, WEB_PORT, json_error_body, raw_http, read_head, request,
    state, ws_connect)
from hardening_station import CONFIG, alive, check, figure, start_daemon, wait_for

_, TOKEN = station.prepare()

t_start = time.monotonic()
try:
    if not start_daemon("daemon"):
        raise SystemExit(1)

    # ---- Row 12: a path that is not UTF-8, an oversized header ------------------------------
    code, head, body = raw_http(
        b"GET /\xff HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
    check(code == 404 and json_error_body(body) is not None,
          f"row 12: GET /\\xff answers 404 with a JSON error: {code} {head[:80]!r} {body[:200]!r}")
    figure(12, f"GET /\\xff: {code} {body[:60].decode('utf-8', 'replace')}")
    big = (b"GET /api/state HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Big: " + b"a" * 100_000 +
           b"\r\nConnection: close\r\n\r\n")
    code, head, body = raw_http(big)
    check(code == 431, f"row 12: a 100 KB header answers 431: {code} {head[:80]!r} {body[:200]!r}")
    figure(12, f"100 KB header: {code}")
    alive(12)

    # ---- Row 1: Host headers that are not UTF-8 ----------------------------------------------
    for host in [b"\xff", b"caf\xe9", b"caf\xe9:" + str(WEB_PORT).encode()]:
        code, head, body = raw_http(b"GET /api/state HTTP/1.1\r\nHost: " + host +
                                    b"\r\nConnection: close\r\n\r\n")
        err = json_error_body(body)
        check(code == 403 and err is not None,
              f"row 1: Host {host!r} answers 403 with a JSON error: {code} {head[:80]!r} "
              f"{body[:200]!r}")
        figure(1, f"Host {host!r}: {code} {err and err['error']!r}")
        alive(1)
    s = ws_connect(host=b"caf\xe9")
    status = read_head(s)
    s.close()
    check(" 403 " in status,
          f"row 1: a WebSocket upgrade with Host b'caf\\xe9' is refused: {status}")
    figure(1, f"WebSocket upgrade with Host b'caf\\xe9': {status}")
    alive(1)

    # ---- §7: a refusal a PC program sees is visible to the operator --------------------------
    s = socket.create_connection(("127.0.0.1", ROT_PORT), timeout=2)
    s.sendall(b"P 100 -20\n")
    got = s.recv(64)
    s.close()
    check(got.startswith(b"RPRT -"), f"§7: a target below the travel is refused: {got!r}")
    events = []

    def refusal_listed():
        events[:] = state().get("events", [])
        return any("refused" in e.get("text", "") and "rotctld" in e.get("text", "")
                   for e in events)
    wait_for("the refusal in /api/state events", refusal_listed, 2.0)
    check(refusal_listed(), f"§7: the refusal is in the console's recent events: {events[:3]}")

    # ---- Row 9: slot numbers beyond 32 bits --------------------------------------------------
    mode_before = state()["mode"]
    for park in [4294967297, -4294967295, 18446744073709551617]:
        r = request("POST", "/api/target", {"park": park}, TOKEN)
        check(r.status == 400 and isinstance(r.body, dict) and r.body.get("field") == "park",
              f"row 9: POST /api/target {{\"park\": {park}}}: {r.status} {r.raw[:200]!r}")
        figure(9, f"POST /api/target park {park}: {r.status}")
    mode_after = state()["mode"]
    check(mode_after == mode_before, f"row 9: the mode stays {mode_before}: {mode_after}")
    file_before = open(CONFIG, "rb").read()
    for slot in [4294967297, -4294967295]:
        r = request("PUT", "/api/config/park",
                    {"slot": slot, "name": "wrapped", "az_deg": 10.0, "el_deg": 5.0}, TOKEN)
        check(r.status == 400 and isinstance(r.body, dict) and r.body.get("field") == "slot",
              f"row 9: PUT /api/config/park slot {slot}: {r.status} {r.raw[:200]!r}")
        figure(9, f"PUT /api/config/park slot {slot}: {r.status}")
    check(open(CONFIG, "rb").read() == file_before, "row 9: the file is unchanged")
    park1 = request("GET", "/api/config").body["park"][0]
    check(park1["name"] == "south" and park1["az_deg"] == 180.0 and park1["el_deg"] == 0.0,
          f"row 9: park slot 1 unchanged: {park1}")
finally:
    station.stop_all()
station.report(t_start)

#!/usr/bin/env python3
"""docs/reliability.md "Hardening" against a real `azeltrack serve` on the simulated antenna: the
settings file: stale temps of dead writers at start, a file overwritten with garbage, the command
line and the console editing it at once, another program holding its lock. Rows as the table
numbers them; each check was written to fail on the code before the fixes. A failure prints what
was sent and what came back, and the daemon's log; hardening_station.py has the station,
hardening_clients.py the clients.

 3  another program holding the config lock: the loop answers, the save waits or fails with 503
 6  `azeltrack config set` while the daemon runs: console saves keep the command line's values
 7  a config file overwritten with garbage: the next save keeps the last one, sets it aside
11  stale temp files of dead writers removed at start; the lock file is 0600

Usage: hardening_config_test.py AZELTRACK"""
import os
import signal
import stat
import subprocess
import time

import hardening_station as station
from hardening_clients import Reply, request, state
from hardening_station import (BIN, CONFIG, LOCK, as_float, check, config_get, config_set, figure,
                               hold_lock, in_thread, poll_state_while, start_daemon)

_, TOKEN = station.prepare()

# Row 11, before the start: the lock file is the daemon's to create (the command line made one),
# and temps left by writers that are dead (a pid above Linux's PID_MAX_LIMIT, 2^22, cannot be
# alive) and by one that is alive (this test).
os.unlink(LOCK)
DEAD_PID = 4194305
try:
    os.kill(DEAD_PID, 0)
    raise SystemExit(f"pid {DEAD_PID} is alive")
except ProcessLookupError:
    pass
stale = [f"{CONFIG}.tmp.{DEAD_PID}", f"{CONFIG}.bak.tmp.{DEAD_PID}"]
live_temp = f"{CONFIG}.tmp.{os.getpid()}"
for path in stale + [live_temp]:
    with open(path, "w") as f:
        f.write('password_hash = "a torn save"\n')

t_start = time.monotonic()
try:
    if not start_daemon("daemon"):
        raise SystemExit(1)

    # ---- Row 11: stale temps removed at start, a live writer's kept --------------------------
    left = [p for p in stale if os.path.exists(p)]
    check(not left, f"row 11: the dead writers' temps are removed at start: left {left}")
    check(os.path.exists(live_temp), "row 11: a live writer's temp is kept")
    log_text = open(station.daemon_log, "rb").read()
    check(b"removed 2 temp file(s)" in log_text,
          f"row 11: the start logs the removal: {log_text[-600:]!r}")
    os.unlink(live_temp)
    figure(11, f"{len(stale)} stale temps of pid {DEAD_PID} removed at start, {len(left)} left; "
               "the live writer's kept")

    # ---- Row 7 (and row 11's lock mode): a config file overwritten with garbage --------------
    r1 = request("PUT", "/api/config/offsets", {"az_offset_deg": 1.0}, TOKEN)
    check(r1.status == 200, f"row 7: first save: {r1.status} {r1.raw[:200]!r}")
    mode = stat.S_IMODE(os.stat(LOCK).st_mode) if os.path.exists(LOCK) else None
    check(mode == 0o600, f"row 11: the daemon's lock file {LOCK} is 0600: {mode and oct(mode)}")
    figure(11, f"lock file mode {mode and oct(mode)} (umask {oct(os.umask(os.umask(0)))})")
    r2 = request("PUT", "/api/config/offsets", {"az_offset_deg": 2.0}, TOKEN)
    check(r2.status == 200, f"row 7: second save: {r2.status} {r2.raw[:200]!r}")
    garbage = b"\x00\xff\xfe[[[ torn \x00\x00 = = \xe9\n" * 8
    with open(CONFIG, "wb") as f:
        f.write(garbage)
    r3 = request("PUT", "/api/config/offsets", {"el_offset_deg": 0.5}, TOKEN)
    check(r3.status == 200,
          f"row 7: the save after the garbage answers 200: {r3.status} {r3.raw[:300]!r}")
    rc = subprocess.run([BIN, "config", "check", "--config", CONFIG], capture_output=True)
    check(rc.returncode == 0,
          f"row 7: the file parses again: rc {rc.returncode} {rc.stderr[-300:]!r}")
    az_off, el_off = as_float(config_get("corrections.az_offset_deg")), as_float(
        config_get("corrections.el_offset_deg"))
    check(az_off == 2.0 and el_off == 0.5,
          f"row 7: the file holds az_offset_deg 2.0 (the second save) and el 0.5: "
          f"{az_off} {el_off}")
    corrupt = CONFIG + ".corrupt"
    check(os.path.exists(corrupt) and open(corrupt, "rb").read() == garbage,
          f"row 7: {corrupt} holds the garbage")
    c = state()["corrections"]
    check(c["az_offset_deg"] == 2.0 and c["el_offset_deg"] == 0.5, f"row 7: applied: {c}")
    figure(7, f"saves {r1.status}/{r2.status}, after garbage {r3.status}; file az_offset {az_off}, "
              f"el_offset {el_off}; .corrupt "
              f"{'holds the garbage' if os.path.exists(corrupt) else 'missing'}")

    # ---- Row 6: the command line and the console edit the same tables -----------------------
    for key, value in [("corrections.el_user_deg", "0.5"), ("park.2.el_deg", "45.0"),
                       ("park.2.name", '"cli slot"')]:
        r = config_set(key, value)
        check(r.returncode == 0, f"row 6: config set {key} {value}: rc {r.returncode} {r.stderr!r}")
    r = request("POST", "/api/correction", {"axis": "az", "steps": 3}, TOKEN)
    check(r.status == 200, f"row 6: correction az +3: {r.status} {r.raw[:200]!r}")
    r = request("PUT", "/api/config/park", {"slot": 1, "name": "Home"}, TOKEN)
    check(r.status == 200, f"row 6: park slot 1 name: {r.status} {r.raw[:200]!r}")
    got = {k: config_get(k) for k in ["corrections.el_user_deg", "park.2.el_deg", "park.2.name",
                                      "corrections.az_user_deg", "park.1.name",
                                      "corrections.az_offset_deg"]}
    check(as_float(got["corrections.el_user_deg"]) == 0.5,
          f"row 6: corrections.el_user_deg from the command line kept: {got}")
    check(as_float(got["park.2.el_deg"]) == 45.0 and got["park.2.name"] == '"cli slot"',
          f"row 6: park slot 2 from the command line kept: {got}")
    az_user = as_float(got["corrections.az_user_deg"])
    check(az_user is not None and abs(az_user - 0.03) < 1e-9 and got["park.1.name"] == '"Home"'
          and as_float(got["corrections.az_offset_deg"]) == 2.0,
          f"row 6: the console's own changes saved, the rest kept: {got}")
    figure(6, f"after two console saves: el_user_deg {got['corrections.el_user_deg']}, park.2 "
              f"{got['park.2.name']} el {got['park.2.el_deg']} (command line); az_user_deg "
              f"{got['corrections.az_user_deg']}, park.1 {got['park.1.name']} (console)")

    # ---- Row 3: another program holds the config lock ----------------------------------------
    holder, t_flock = hold_lock(4)
    t_hold = time.monotonic()
    saver, out = in_thread(lambda: request("PUT", "/api/config/band", {"band": "432"}, TOKEN,
                                           timeout=10))
    worst, n, bad = poll_state_while(saver.is_alive)
    saver.join()
    save = out[0]
    secs = save.seconds if isinstance(save, Reply) else float("nan")
    check(worst < 0.1 and not bad,
          f"row 3: /api/state within 100 ms while the lock is held: worst {worst * 1000:.1f} ms "
          f"of {n}, bad {bad}")
    ok = isinstance(save, Reply) and save.status == 200
    check(ok, f"row 3: the save answers 200 once the lock is released: {save}")
    after_release = len(out) == 2 and out[1] >= t_flock + 4.0
    check(after_release, f"row 3: the save answered after the lock was released (flock started "
                         f"{out[1] - t_flock:.2f} s before the answer, sleeps 4 s)")
    holder.wait()
    check(request("GET", "/api/config").body["band"] == "432", "row 3: band 432 saved")
    figure(3, f"lock held 4 s: /api/state worst {worst * 1000:.1f} ms of {n}; the save answered "
              f"{save.status if ok else save} after {secs:.2f} s "
              f"({out[1] - t_hold:.2f} s after flock took the lock)")

    file_before = open(CONFIG, "rb").read()
    holder, t_flock = hold_lock(8)
    saver, out = in_thread(lambda: request("PUT", "/api/config/band", {"band": "1296"}, TOKEN,
                                           timeout=10))
    worst, n, bad = poll_state_while(saver.is_alive)
    saver.join()
    save = out[0]
    secs = save.seconds if isinstance(save, Reply) else float("nan")
    still_held = holder.poll() is None
    os.killpg(holder.pid, signal.SIGTERM)  # done with it: no need to wait out the 8 s
    holder.wait()
    ok = isinstance(save, Reply) and save.status == 503
    check(ok and 4.5 <= save.seconds <= 6.0 and still_held,
          f"row 3: a lock held 8 s fails the save with 503 after ~5 s: {save}, held {still_held}")
    err = save.body.get("error", "") if ok and isinstance(save.body, dict) else ""
    check(LOCK in err, f"row 3: the error names the lock file {LOCK}: {err!r}")
    check(open(CONFIG, "rb").read() == file_before, "row 3: the file is unchanged after the 503")
    check(request("GET", "/api/config").body["band"] == "432", "row 3: the band stays 432")
    check(worst < 0.1 and not bad,
          f"row 3: /api/state within 100 ms during the failed save: worst {worst * 1000:.1f} ms")
    figure(3, f"lock held 8 s: the save answered {save.status if isinstance(save, Reply) else save}"
              f" after {secs:.2f} s ({err!r}); /api/state worst "
              f"{worst * 1000:.1f} ms of {n}; file unchanged")
finally:
    station.stop_all()
station.report(t_start)

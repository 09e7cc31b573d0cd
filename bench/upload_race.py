#!/usr/bin/env python3
"""Eight package uploads racing (docs/reliability.md "Hardening, round three": row 10 and the
benchmark): eight curl processes each send a 60 MiB package to a logged-in daemon at once, while GET
/api/state is asked every 10 ms. Before the fix all eight bodies were read into memory (RSS 15 ->
496 MiB) before seven were refused, the tick was 33 ms late and /api/state took 74 ms.

Measured: the daemon's resident memory before and its peak (VmHWM) after, how the uploads were
answered, the latency of every /api/state (p50, p99, max) and the control tick's lateness over
the run (the daemon's own statistics, printed when it stops). A Markdown table goes to stdout.

The race is run ROUNDS times (the inbox emptied between rounds, as the helper would), so that
the percentiles rest on some hundreds of requests.

Usage: bench/upload_race.py BUILD_DIR [UPLOADS] [MIB] [ROUNDS]   (default 8 of 60 MiB, 10 rounds)"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "integration"))
from daemon_harness import (free_port, http_json, station_toml, upload_test_deb,  # noqa: E402
                            wait_until)

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
UPLOADS = int(sys.argv[2]) if len(sys.argv) > 2 else 8
MIB = int(sys.argv[3]) if len(sys.argv) > 3 else 60
ROUNDS = int(sys.argv[4]) if len(sys.argv) > 4 else 10
BIN = os.path.realpath(os.path.join(BUILD, "azeltrack"))
TMP = tempfile.mkdtemp(prefix="azt-upload-race-")
PORT = free_port()
BASE = f"http://127.0.0.1:{PORT}"


def kib(pid, field):
    with open(f"/proc/{pid}/status", encoding="ascii") as f:
        return int(re.search(rf"^{field}:\s+(\d+) kB", f.read(), re.M).group(1))


def upload(path, token, out):
    r = subprocess.run(["curl", "-sS", "-o", "/dev/null", "-w", "%{http_code}",
                        "-H", f"Authorization: Bearer {token}", "-X", "POST", "-T", path,
                        f"{BASE}/api/software/update"], capture_output=True, text=True, timeout=300)
    out.append(r.stdout.strip() or r.stderr.strip())


def race(deb, token, answers, latencies):
    """One round: UPLOADS at once, GET /api/state every 10 ms until all are answered."""
    threads = [threading.Thread(target=upload, args=(deb, token, answers))
               for _ in range(UPLOADS)]
    for t in threads:
        t.start()
    while any(t.is_alive() for t in threads):
        t0 = time.monotonic()
        http_json(BASE, "GET", "/api/state")
        latencies.append(time.monotonic() - t0)
        time.sleep(0.01)


def pct(values, p):
    values = sorted(values)
    return values[min(len(values) - 1, int(p * len(values)))] * 1000 if values else float("nan")


def main():
    config = os.path.join(TMP, "azeltrack.toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(PORT))
    token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                           capture_output=True, text=True).stdout.strip()
    deb = upload_test_deb(TMP, MIB * 2**20)
    daemon = subprocess.Popen([BIN, "serve", "--config", config, "--update-inbox",
                               os.path.join(TMP, "inbox"), "--update-status",
                               os.path.join(TMP, "status")], stderr=subprocess.PIPE, text=True)
    try:
        wait_until(lambda: http_json(BASE, "GET", "/api/state")[0] == 200, 20)
        time.sleep(2)  # settled: the start's allocations done
        with open(f"/proc/{daemon.pid}/clear_refs", "w", encoding="ascii") as f:
            f.write("5")  # resets the peak (VmHWM) to now: the start's own peak is not counted
        rss_before = kib(daemon.pid, "VmRSS")
        answers, latencies = [], []
        for _ in range(ROUNDS):
            race(deb, token, answers, latencies)
            # The helper's part: the inbox is empty again, so the next round's upload is taken.
            os.remove(os.path.join(TMP, "inbox", "request.deb"))
        peak = kib(daemon.pid, "VmHWM")
    finally:
        daemon.terminate()
        _, err = daemon.communicate(timeout=20)
        shutil.rmtree(TMP, ignore_errors=True)
    tick = re.search(r"late p50 ([\d.]+) ms p99 ([\d.]+) ms max ([\d.]+) ms", err)
    counts = {a: answers.count(a) for a in sorted(set(answers))}
    print(f"| {UPLOADS} uploads of {MIB} MiB, {ROUNDS} rounds | value |\n| --- | --- |")
    print(f"| answers | {counts} |")
    print(f"| RSS before, peak | {rss_before / 1024:.0f} MiB, {peak / 1024:.0f} MiB "
          f"(growth {(peak - rss_before) / 1024:.0f} MiB) |")
    print(f"| /api/state p50 / p99 / max | {pct(latencies, 0.5):.1f} / {pct(latencies, 0.99):.1f} / "
          f"{pct(latencies, 1.0):.1f} ms ({len(latencies)} requests) |")
    print(f"| tick lateness p50 / p99 / max | "
          f"{' / '.join(tick.groups()) + ' ms' if tick else 'not printed'} |")


if __name__ == "__main__":
    main()

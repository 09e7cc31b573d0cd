#!/usr/bin/env python3
"""The daemon's shutdown under valgrind's memcheck, with work in flight (docs/reliability.md
"Hardening, round three" row 5): a 16 MiB package upload (hashed and written on the worker: seconds
under memcheck) and a burst of Software-page looks, then SIGTERM at 1.5, 3 and 4.5 s. The red-team
report: memcheck found 26 invalid reads in the worker's jobs on memory the console's destructor had
freed, and a folder with a garbage name appeared in the daemon's working directory. (This bounded
version did not catch that on the old code in three tries: its timing is the machine's. The
deterministic regression test is SoftwareUpdates.QueuedWorkOutlivesTheObjectThatQueuedIt.) Now the
daemon finishes its workers before destroying any part: no memcheck error (exit code 0, not
valgrind's 99), nothing new in its working directory, and the upload either stored whole or not at
all. Three rounds, SIGTERM at a different moment of each. The bounded version in the test command;
`scripts/test-memcheck` runs more rounds, and the integration suite against the ASan program.
Usage: shutdown_memcheck_test.py AZELTRACK [ROUNDS]   (skipped, 77, without valgrind)"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

from daemon_harness import (Checks, free_port, http_json, station_toml, upload_test_deb,
                            wait_until)

VALGRIND = shutil.which("valgrind")
if not VALGRIND:
    print("shutdown_memcheck: valgrind is not installed (scripts/install-deps --test)")
    sys.exit(77)
BIN = os.path.realpath(sys.argv[1])
if "libasan" in subprocess.run(["ldd", BIN], capture_output=True, text=True).stdout:
    print("shutdown_memcheck: an AddressSanitizer build; memcheck cannot run it (ASan checks it)")
    sys.exit(77)
ROUNDS = int(sys.argv[2]) if len(sys.argv) > 2 else 3
MIB = 16  # hashed and written on the worker: seconds under memcheck, so SIGTERM finds it busy
check = Checks()


def one_round(n, delay_s):
    tmp = tempfile.mkdtemp(prefix="azt-memcheck-")
    cwd = os.path.join(tmp, "cwd")
    os.makedirs(cwd)
    port = free_port()
    base = f"http://127.0.0.1:{port}"
    config = os.path.join(tmp, "azeltrack.toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(port))
    token = subprocess.run([BIN, "web", "token", "--config", config], check=True,
                           capture_output=True, text=True).stdout.strip()
    subprocess.run([BIN, "web", "password", "--config", config], input=b"a-long-password\n",
                   check=True, capture_output=True)
    deb = upload_test_deb(tmp, MIB * 2**20)
    log_path = os.path.join(tmp, "memcheck.log")
    daemon = subprocess.Popen(
        [VALGRIND, "--tool=memcheck", "--error-exitcode=99", "--leak-check=no",
         f"--log-file={log_path}", BIN, "serve", "--config", config, "--update-inbox",
         os.path.join(tmp, "inbox"), "--update-status", os.path.join(tmp, "status")],
        cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        up = wait_until(lambda: http_json(base, "GET", "/api/state", timeout=10)[0] == 200, 120, 0.5)
        check(up, f"round {n}: the daemon answers under memcheck")
        upload = subprocess.Popen(["curl", "-sS", "-o", "/dev/null", "-H",
                                   f"Authorization: Bearer {token}", "-X", "POST", "-T", deb,
                                   f"{base}/api/software/update"],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        looks = [threading.Thread(target=lambda: http_json(base, "GET", "/api/software",
                                                           timeout=30), daemon=True)
                 for _ in range(6)]
        for t in looks:
            t.start()
        time.sleep(delay_s)
        daemon.send_signal(signal.SIGTERM)
        code = daemon.wait(120)
        upload.wait(30)
        errors = open(log_path, encoding="utf-8", errors="replace").read()
        summary = [line for line in errors.splitlines() if "ERROR SUMMARY" in line]
        check(code == 0 and "Invalid read" not in errors and "Invalid write" not in errors,
              f"round {n} (SIGTERM after {delay_s:.1f} s): exit {code}, {summary}\n{errors[-3000:]}")
        check(os.listdir(cwd) == [], f"round {n}: nothing appeared in the working directory: "
              f"{os.listdir(cwd)}")
        stored = os.path.join(tmp, "inbox", "request.deb")
        if os.path.exists(stored):
            check(os.path.getsize(stored) == os.path.getsize(deb),
                  f"round {n}: the upload stored whole or not at all")
        print(f"shutdown_memcheck: round {n}: SIGTERM after {delay_s:.1f} s, exit {code}, "
              f"{summary[-1].split('== ')[-1] if summary else 'no summary'}; upload "
              f"{'stored' if os.path.exists(stored) else 'not stored'}")
    finally:
        if daemon.poll() is None:
            daemon.kill()
            daemon.wait()
        shutil.rmtree(tmp, ignore_errors=True)


for n in range(ROUNDS):
    one_round(n + 1, 1.5 + 1.5 * (n % 3) + 0.25 * (n // 3))
sys.exit(check.summary("shutdown_memcheck"))

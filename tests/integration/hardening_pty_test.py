#!/usr/bin/env python3
"""docs/reliability.md "Hardening" against a real `azeltrack serve` on the simulated antenna: the
pseudo-terminals: a client that does not read its replies, and a directory that is not the daemon's
own. Rows as the table numbers them; each check was written to fail on the code before the fixes. A
failure prints what was sent and what came back, and the daemon's log; hardening_station.py has the
station, hardening_clients.py the clients.

 8  a pseudo-terminal client that does not read: the next client gets no stale bytes, also when
    the daemon was descheduled (SIGSTOP) while the first client wrote and the next one opened
10  a pseudo-terminal directory of another user, or a symbolic link: refused at start

Usage: hardening_pty_test.py AZELTRACK"""
import os
import pwd
import signal
import subprocess
import time

import hardening_station as station
from daemon_harness import station_toml
from hardening_station import BIN, GS232B, TMP, alive, check, figure, start_daemon, stop_daemon

station.prepare()

t_start = time.monotonic()
try:
    if not start_daemon("daemon"):
        raise SystemExit(1)

    # ---- Row 8: a pseudo-terminal client that does not read its replies ---------------------
    def read_until_cr(fd, seconds=2.0):
        """What a non-blocking pty reads until a reply's CR, or `seconds`."""
        got = b""
        end = time.monotonic() + seconds
        while time.monotonic() < end and b"\r" not in got:
            try:
                got += os.read(fd, 65536)
            except BlockingIOError:
                time.sleep(0.01)
        return got

    def unread_then_next(descheduled):
        """A client writes 300 C2 and closes without reading; a new client opens the path and
        reads after 0.3 s (the row's definition), then sends its own C2. With `descheduled` the
        daemon is stopped (SIGSTOP) from before the first client's writes until the new client
        has opened, as a loaded machine may leave it: the replies it then makes to the commands
        of the client that left must not reach the new one either. Returns (stale, reply)."""
        if descheduled:
            os.kill(station.daemon.pid, signal.SIGSTOP)
        try:
            fd = os.open(GS232B, os.O_RDWR | os.O_NOCTTY)
            for _ in range(300):
                os.write(fd, b"C2\r")
            os.close(fd)
            fd = os.open(GS232B, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        finally:
            if descheduled:
                os.kill(station.daemon.pid, signal.SIGCONT)
        try:
            time.sleep(0.3)
            try:
                stale_bytes = os.read(fd, 65536)
            except BlockingIOError:
                stale_bytes = b""
            os.write(fd, b"C2\r")
            got = read_until_cr(fd)
            quiet_end = time.monotonic() + 0.3  # and nothing more after it
            while time.monotonic() < quiet_end:
                try:
                    got += os.read(fd, 65536)
                except BlockingIOError:
                    time.sleep(0.01)
        finally:
            os.close(fd)
        return stale_bytes, got

    for descheduled in (False, True):
        how = "daemon descheduled meanwhile" if descheduled else "next client opens at once"
        stale_bytes, got = unread_then_next(descheduled)
        check(stale_bytes == b"", f"row 8 ({how}): a new client reads 0 stale bytes 0.3 s after "
                                  f"opening: {len(stale_bytes)} ({stale_bytes[:48]!r}...)")
        replies = got.count(b"AZ=")
        check(replies == 1 and got.count(b"\r") == 1,
              f"row 8 ({how}): the client's own C2 gets one reply: {replies} replies, "
              f"{len(got)} bytes ({got[:48]!r}...)")
        figure(8, f"{how}: 300 unread C2, next client read {len(stale_bytes)} stale bytes; its C2 "
                  f"got {replies} repl{'y' if replies == 1 else 'ies'} ({len(got)} bytes, "
                  f"{got[:16]!r})")
        alive(8)

    # A client that leaves in the middle of a command: its half line must not prefix the next
    # client's first command (the session starts afresh at a hang-up).
    fd = os.open(GS232B, os.O_RDWR | os.O_NOCTTY)
    os.write(fd, b"W12")
    time.sleep(0.2)  # read by the daemon before the hang-up
    os.close(fd)
    time.sleep(0.2)
    fd = os.open(GS232B, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    try:
        os.write(fd, b"C2\r")
        got = read_until_cr(fd)
    finally:
        os.close(fd)
    check(got.startswith(b"AZ="), f"row 8: a half line left by a client that hung up does not "
                                  f"spoil the next one's C2: {got[:48]!r}")
    alive(8)

    stop_daemon()

    # ---- Row 10: pseudo-terminal directories that are not the daemon's own ------------------
    def pty_config(name, directory):
        path = os.path.join(TMP, f"{name}.toml")
        with open(path, "w") as f:
            f.write(station_toml() + f'[[serial]]\nprotocol = "gs232b"\ndevice = "pty:{directory}/gs232b"\n')
        return path

    def serve(path):
        return subprocess.run([BIN, "serve", "--config", path, "--run-for", "1"],
                              capture_output=True, timeout=20)

    own = os.path.join(TMP, "own-pty")
    r = serve(pty_config("own", own))  # the control: the same file with our own directory starts
    check(r.returncode == 0, f"row 10: control: a directory of our own: rc {r.returncode} "
                             f"{r.stderr[-300:]!r}")
    real = os.path.join(TMP, "real-pty")
    os.mkdir(real, 0o700)
    link = os.path.join(TMP, "link-pty")
    os.symlink(real, link)
    r = serve(pty_config("symlink", link))
    check(r.returncode == 2 and link.encode() in r.stderr,
          f"row 10: a symbolic link as the pty directory is refused: rc {r.returncode} "
          f"{r.stderr[-300:]!r}")
    check(not os.path.exists(os.path.join(real, "gs232b")), "row 10: no link made through it")
    figure(10, f"symlinked directory: rc {r.returncode}, "
               f"{r.stderr.decode(errors='replace').strip().splitlines()[-1:]}")
    if os.geteuid() != 0:
        print("skip: row 10: a directory of another user needs root to chown it")
    else:
        theirs = os.path.join(TMP, "nobody-pty")
        os.mkdir(theirs, 0o755)
        nobody = pwd.getpwnam("nobody")
        os.chown(theirs, nobody.pw_uid, nobody.pw_gid)
        r = serve(pty_config("nobody", theirs))
        check(r.returncode == 2 and theirs.encode() in r.stderr,
              f"row 10: another user's pty directory is refused: rc {r.returncode} "
              f"{r.stderr[-300:]!r}")
        check(not os.path.exists(os.path.join(theirs, "gs232b")), "row 10: no link made in it")
        figure(10, f"directory of nobody: rc {r.returncode}, "
                   f"{r.stderr.decode(errors='replace').strip().splitlines()[-1:]}")
finally:
    station.stop_all()
station.report(t_start)

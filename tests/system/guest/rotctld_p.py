#!/usr/bin/env python3
"""Part of the system test inside the machine: asks the daemon's rotctld for its position (`p`)
and prints what came back, whole, within 3 s; exit 0 only for the two lines of an answer."""
import socket
import sys


def main():
    data = b""
    try:
        with socket.create_connection(("127.0.0.1", 4533), timeout=3) as s:
            s.sendall(b"p\n")
            while data.count(b"\n") < 2:
                chunk = s.recv(256)
                if not chunk:
                    break
                data += chunk
    except OSError as e:
        print(f"rotctld: {e}; received {data!r}")
        return 1
    print(f"rotctld answered {data!r}")
    return 0 if data.count(b"\n") == 2 and b"RPRT" not in data else 1


if __name__ == "__main__":
    sys.exit(main())

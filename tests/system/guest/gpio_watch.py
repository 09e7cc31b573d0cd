#!/usr/bin/env python3
"""Part of the system test inside the machine (guest/run): drives one gpio-sim input and reads
the output lines back, timed. Writes PULL to line LINE's `pull` (what a switch or the PTT does to
the Pi's pin), then reads the `value` of each output line as fast as it can for SECONDS, printing
"t_s bits" at the start and at every change, t from the moment of the write. Python rather than
the shell: a loop that forks (date, awk) takes tens of milliseconds a turn under TCG.

Usage: gpio_watch.py SIM_DIR LINE PULL SECONDS OUTPUT_LINE..."""
import sys
import time


def main():
    sim, line, pull, seconds = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    files = [open(f"{sim}/sim_gpio{n}/value", encoding="ascii") for n in sys.argv[5:]]

    def bits():
        out = ""
        for f in files:
            f.seek(0)
            out += f.read().strip()
        return out

    last = bits()
    with open(f"{sim}/sim_gpio{line}/pull", "w", encoding="ascii") as f:
        t0 = time.monotonic()
        f.write(pull)
    print(f"0.000 {last}")
    while time.monotonic() - t0 < seconds:
        now = bits()
        if now != last:
            print(f"{time.monotonic() - t0:.3f} {now}", flush=True)
            last = now


if __name__ == "__main__":
    main()

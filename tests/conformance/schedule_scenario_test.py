#!/usr/bin/python3
"""The crafted schedule scenario (tests/data/sat/schedule_scenario.{tle,json}) holds, and
`azeltrack schedule` sees it as skyfield does.

Usage: /usr/bin/python3 schedule_scenario_test.py AZELTRACK

The daemon's schedule test relies on three satellites whose passes are placed around an instant
T0 (make_schedule_scenario.py). Here, independently of the generator's own run:
  * the files agree, the checksums hold, the epochs are within 2 days of T0;
  * skyfield finds exactly one pass of each from T0 - 600 s to T0 + 900 s, at the times and
    highest elevation the json lists (0.15 s, 0.01 deg), inside the windows promised
    (A: AOS +20 +-5, LOS +110 +-15; B: AOS +45 +-5, LOS +80 +-10, inside A; C: AOS +165 +-15,
    LOS +235 +-30);
  * `azeltrack passes` finds the same passes within 1 s, and `azeltrack schedule` with the
    priority list B, A, C (all take_over) plans A from its AOS, B taking over at its AOS, A
    again from B's LOS to its own, then C: each switch within 1 s of the json, and the whole plan
    step for step as the documented rules give it (schedule_skyfield_oracle.py).
"""
import datetime
import json
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from schedule_skyfield_oracle import SkyPasses, plan as oracle_plan  # noqa: E402
import schedule_skyfield_test as base  # noqa: E402

DATA = os.path.join(HERE, "..", "data", "sat")
BEFORE_S, AFTER_S = 600.0, 900.0
PROMISED = {"A": ((20.0, 5.0), (110.0, 15.0)), "B": ((45.0, 5.0), (80.0, 10.0)),
            "C": ((165.0, 15.0), (235.0, 30.0))}
failures = base.failures
check = base.check


def files_agree(doc, tle_lines, t0_dt):
    from sgp4.api import Satrec
    from sgp4.io import verify_checksum

    want = []
    for s in doc["satellites"]:
        want += [s["name"], s["line1"], s["line2"]]
        for line in (s["line1"], s["line2"]):
            try:
                verify_checksum(line)
            except ValueError as e:
                check(False, "%s: %s" % (s["name"], e))
        sat = Satrec.twoline2rv(s["line1"], s["line2"])
        epoch = datetime.datetime(1949, 12, 31, tzinfo=datetime.timezone.utc) + \
            datetime.timedelta(days=sat.jdsatepoch + sat.jdsatepochF - 2433281.5)
        check(abs((epoch - t0_dt).total_seconds()) <= 2 * 86400.0,
              "%s: epoch %s is not within 2 days of T0" % (s["name"], epoch))
    check(tle_lines == want, "schedule_scenario.tle and .json hold different element sets")


def skyfield_passes(doc, ts, site, t0):
    """{letter: (pass seconds after T0, SkyPasses)}: exactly one pass each in the quiet window."""
    from skyfield.api import EarthSatellite

    start = ts.tt_jd(t0.tt - BEFORE_S / 86400.0)
    out = {}
    for s in doc["satellites"]:
        letter = s["name"][-1]
        sp = SkyPasses(ts, EarthSatellite(s["line1"], s["line2"], s["name"], ts), site, start,
                       BEFORE_S + AFTER_S, doc["horizon_deg"])
        found = sp.find(tol_s=0.01)
        if not check(len(found) == 1, "%s: %d passes from T0-600 s to T0+900 s" %
                     (s["name"], len(found))):
            continue
        p = {k: found[0][k] - BEFORE_S for k in ("aos", "los")}
        p["max_el"] = found[0]["max_el"]
        j = s["pass"]
        check(abs(p["aos"] - j["aos_s"]) <= 0.15 and abs(p["los"] - j["los_s"]) <= 0.15 and
              abs(p["max_el"] - j["max_el_deg"]) <= 0.01,
              "%s: skyfield %r, the json %r" % (s["name"], p, j))
        (aos, aos_tol), (los, los_tol) = PROMISED[letter]
        check(abs(p["aos"] - aos) <= aos_tol and abs(p["los"] - los) <= los_tol,
              "%s: AOS %+.1f, LOS %+.1f outside the promised windows" %
              (s["name"], p["aos"], p["los"]))
        out[letter] = (p, sp)
    if "A" in out and "B" in out:
        check(out["A"][0]["aos"] < out["B"][0]["aos"] and out["B"][0]["los"] < out["A"][0]["los"],
              "B's pass is not inside A's")
    return out


def config(doc):
    site = doc["site"]
    sc = {"lat": site["lat_deg"], "lon": site["lon_deg"], "alt_m": site["alt_m"],
          "mask": doc["horizon_deg"],
          "schedule": [(str(s["norad"]), 0.0, "take_over")
                       for k in "BAC" for s in doc["satellites"] if s["name"].endswith(k)]}
    return sc, base.config_text(sc, doc["dut1_s"])


def azeltrack_agrees(azeltrack, doc, sky, t0_dt):
    sc, text = config(doc)
    frm = t0_dt - datetime.timedelta(seconds=BEFORE_S)
    frm_iso = frm.strftime("%Y-%m-%dT%H:%M:%SZ")
    hours = (BEFORE_S + AFTER_S + 300.0) / 3600.0

    def after_t0(iso):
        t = datetime.datetime.fromisoformat(iso.replace("Z", "+00:00"))
        return (t - t0_dt).total_seconds()

    for s in doc["satellites"]:
        out = base.run([azeltrack, "passes", str(s["norad"]), "--tle", TLE, "--lat",
                        repr(sc["lat"]), "--lon", repr(sc["lon"]), "--alt", repr(sc["alt_m"]),
                        "--dut1", repr(doc["dut1_s"]), "--from", frm_iso, "--hours",
                        repr(hours), "--json"])
        got = [json.loads(line) for line in out.splitlines() if line.strip()]
        ok = len(got) == 1 and abs(after_t0(got[0]["aos"]) - s["pass"]["aos_s"]) <= 1.0 and \
            abs(after_t0(got[0]["los"]) - s["pass"]["los_s"]) <= 1.0
        check(ok, "%s: azeltrack passes %r, the json %r" % (s["name"], got, s["pass"]))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "scenario.toml")
        with open(path, "w") as f:
            f.write(text)
        plan = json.loads(base.run([azeltrack, "schedule", "--config", path, "--tle", TLE,
                                    "--from", frm_iso, "--hours", repr(hours), "--json"]))
    steps = [dict(s, **{"from": after_t0(s["from"]), "to": after_t0(s["to"])})
             for s in plan["plan"]]
    tracks = [(s["sat"][-1], s["from"], s["to"]) for s in steps if s["kind"] == "track"]
    a, b, c = (sky[k][0] for k in "ABC")
    want = [("A", a["aos"], b["aos"]), ("B", b["aos"], b["los"]), ("A", b["los"], a["los"]),
            ("C", c["aos"], c["los"])]
    same = len(tracks) == len(want) and all(
        t[0] == w[0] and abs(t[1] - w[1]) <= 1.0 and abs(t[2] - w[2]) <= 1.0
        for t, w in zip(tracks, want))
    check(same, "azeltrack schedule tracks %r, expected %r" % (tracks, want))
    # The whole plan, pre-positions and the park after C, as the rules give it (T0 - 600 s is 0).
    prio = {"B": 0, "A": 1, "C": 2}
    passes = [{"prio": prio[k], "aos": p["aos"] + BEFORE_S, "los": p["los"] + BEFORE_S,
               "max_el": p["max_el"],
               "sky": lambda t, sp=sp: tuple(map(float, sp.look(t)))}
              for k, (p, sp) in sky.items()]
    shifted = [dict(s, **{"from": s["from"] + BEFORE_S, "to": s["to"] + BEFORE_S})
               for s in steps]
    entries = [{"min_el": 0.0, "preempt": "take_over"}] * 3
    norads = [int(n) for n, _, _ in sc["schedule"]]
    base.compare_plans({"name": "scenario"},
                       oracle_plan(entries, passes, base.RULES, hours * 3600.0, base.PARK),
                       shifted, norads)
    print("scenario: passes %s; tracks %s" %
          ({k: (round(p["aos"], 1), round(p["los"], 1)) for k, (p, _) in sky.items()},
           [(k, round(f, 1), round(t, 1)) for k, f, t in tracks]))


TLE = os.path.join(DATA, "schedule_scenario.tle")


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    from skyfield.api import load, wgs84

    with open(os.path.join(DATA, "schedule_scenario.json")) as f:
        doc = json.load(f)
    with open(TLE) as f:
        tle_lines = [line.rstrip("\n") for line in f if line.strip()]
    t0_dt = datetime.datetime.fromisoformat(doc["t0"].replace("Z", "+00:00"))
    ts = load.timescale(builtin=True)
    t0 = ts.from_datetime(t0_dt)
    check(abs(float(t0.dut1) - doc["dut1_s"]) < 1e-3, "the json's dut1_s is not skyfield's")
    files_agree(doc, tle_lines, t0_dt)
    site = wgs84.latlon(doc["site"]["lat_deg"], doc["site"]["lon_deg"], doc["site"]["alt_m"])
    sky = skyfield_passes(doc, ts, site, t0)
    if len(sky) == 3:
        azeltrack_agrees(argv[1], doc, sky, t0_dt)
    for f in failures:
        print("FAIL:", f)
    print("schedule scenario:", "FAILED" if failures else "ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

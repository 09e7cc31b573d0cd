#!/usr/bin/python3
"""`azeltrack schedule` against an independent schedule: skyfield's passes, the documented rules.

Usage: /usr/bin/python3 schedule_skyfield_test.py AZELTRACK

The catalogue is tests/data/sat/schedule_catalogue.tle, 20 element sets: ISS (ZARYA) and NOAA 19
are real (CelesTrak, 1 March 2024); the other 18 are DERIVED from real LEO families by varying
inclination, RAAN, mean anomaly and mean motion, at the epoch 2024-03-01 12:00 UTC, with checksums
recomputed (tests/data/sat/make_schedule_catalogue.py says how). Each scenario is a station, a flat
horizon (`[satellites] mask`) and a priority list of six of them with a mix of min_el_deg and
preempt rules, planned for 24 h from the elements' epoch.

For each scenario, independently of azeltrack's code:
  * every pass of the scheduled satellites comes from skyfield (find_events, then AOS/LOS by
    bisection to 0.02 s, the culmination by golden section; a 20 s scan adds any grazing pass
    find_events leaves out) over the same horizon as azeltrack's pass search: the geometric
    elevation of (satellite - site), no refraction, no light time, against the mask
    (schedule_skyfield_oracle.py says why that is azeltrack's definition); skyfield's own UT1-UTC
    is given to azeltrack as [sky] dut1_s;
  * the plan is rebuilt from docs/satellites.md "The schedule" (schedule_skyfield_oracle.py), with
    the rates of [mount.az] / [mount.el] (what `azeltrack schedule` plans with), 5 s to settle,
    10 idle minutes before parking at park slot 1.
Then: azeltrack's passes (`azeltrack passes`) equal skyfield's within 1 s; its plan equals the
rebuilt one step for step (kind, satellite, both ends within 1 s); and, read from azeltrack's plan
alone, the rules hold: every track sees its satellite up and starts and ends at an AOS, a LOS or a
switch; no pass of a higher priority that meets its minimum elevation is left for a lower one
unless that pass's rule is "finish" and the lower one was already running; a switch in the middle
of a pass is a "take_over" at its AOS; each pre-position ends at the AOS it prepares and lasts at
least the slew from where the antenna was (or starts when the antenna became free); parks follow
10 idle minutes. The scenarios together must take over, make a "finish" pass wait, resume a pass,
leave a pass below its minimum elevation out, and park.
"""
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from schedule_skyfield_oracle import SkyPasses, plan as oracle_plan, slew_s, worked  # noqa: E402

CATALOGUE = os.path.join(HERE, "..", "data", "sat", "schedule_catalogue.tle")
FROM = datetime.datetime(2024, 3, 1, 12, 0, 0, tzinfo=datetime.timezone.utc)
HOURS = 24.0
SPAN_S = HOURS * 3600.0
TOL_S = 1.0

# The mount and its park slot 1, written into the configuration; settle and idle time are the
# documented constants of docs/satellites.md "The schedule".
AZ_RATE, EL_RATE, PARK = 1.5, 1.0, (180.0, 0.0)
RULES = {"az_rate": AZ_RATE, "el_rate": EL_RATE, "settle_s": 5.0, "idle_park_s": 600.0,
         "park_sky": PARK}

SCENARIOS = [
    {"name": "FN06HE (46.2 N), flat 0 deg horizon", "lat": 46.189, "lon": -79.393, "alt_m": 300.0,
     "mask": 0.0,
     "schedule": [("90006", 3.0, "finish"), ("90016", 0.0, "take_over"),
                  ("90002", 6.0, "finish"), ("90015", 0.0, "take_over"),
                  ("90012", 3.0, "finish"), ("25544", 6.0, "take_over")]},
    {"name": "JF96 (34 S), flat 5 deg horizon", "lat": -33.94, "lon": 18.47, "alt_m": 40.0,
     "mask": 5.0,
     "schedule": [("90007", 6.0, "finish"), ("90009", 20.0, "finish"),
                  ("90017", 3.0, "take_over"), ("90002", 0.0, "take_over"),
                  ("90013", 0.0, "take_over"), ("90015", 20.0, "take_over")]},
]

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
    return ok


def seconds(iso):
    t = datetime.datetime.fromisoformat(iso.replace("Z", "+00:00"))
    return (t - FROM).total_seconds()


def config_text(sc, dut1_s):
    lines = ["schema_version = 2", "[station]", "lat_deg = %r" % sc["lat"],
             "lon_deg = %r" % sc["lon"], "alt_m = %r" % sc["alt_m"], "[sky]",
             "dut1_s = %r" % dut1_s, "[mount.az]", "max_rate_deg_s = %r" % AZ_RATE,
             "[mount.el]", "max_rate_deg_s = %r" % EL_RATE, "[[park]]", 'name = "slot 1"',
             "az_deg = %r" % PARK[0], "el_deg = %r" % PARK[1], "[satellites]",
             'mask = "%r"' % sc["mask"]]
    for sat, min_el, preempt in sc["schedule"]:
        lines += ["[[schedule]]", 'sat = "%s"' % sat, "min_el_deg = %r" % min_el,
                  'preempt = "%s"' % preempt]
    return "\n".join(lines) + "\n"


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    if r.returncode != 0:
        raise SystemExit("FAIL: %s: exit %d: %s" % (" ".join(cmd), r.returncode, r.stderr))
    return r.stdout


def azeltrack_passes(azeltrack, sc, norad, dut1_s):
    out = run([azeltrack, "passes", norad, "--tle", CATALOGUE, "--lat", repr(sc["lat"]),
               "--lon", repr(sc["lon"]), "--alt", repr(sc["alt_m"]), "--dut1", repr(dut1_s),
               "--min-el", repr(sc["mask"]), "--from", FROM.strftime("%Y-%m-%dT%H:%M:%SZ"),
               "--hours", repr(HOURS), "--json"])
    return [json.loads(line) for line in out.splitlines() if line.strip()]


def compare_passes(sc, norad, ours, theirs):
    """azeltrack's pass search against skyfield's, pass for pass."""
    if not check(len(ours) == len(theirs), "%s %s: skyfield %d passes, azeltrack %d" %
                 (sc["name"], norad, len(ours), len(theirs))):
        return 0.0
    worst = 0.0
    for p, a in zip(ours, theirs):
        d = max(abs(seconds(a["aos"]) - p["aos"]), abs(seconds(a["los"]) - p["los"]))
        worst = max(worst, d)
        check(d <= TOL_S and abs(a["max_el_deg"] - p["max_el"]) < 0.05,
              "%s %s: pass %.1f-%.1f (max %.3f) vs azeltrack %s-%s (max %.3f)" %
              (sc["name"], norad, p["aos"], p["los"], p["max_el"], a["aos"], a["los"],
               a["max_el_deg"]))
    return worst


def compare_plans(sc, expected, steps, norads):
    """Step for step: kind, satellite, both ends within 1 s."""
    check(len(expected) == len(steps), "%s: %d steps expected, azeltrack planned %d" %
          (sc["name"], len(expected), len(steps)))
    for k, (e, s) in enumerate(zip(expected, steps)):
        want_norad = None if e["prio"] is None else norads[e["prio"]]
        same = (e["kind"] == s["kind"] and want_norad == s["norad"] and
                abs(e["from"] - s["from"]) <= TOL_S and abs(e["to"] - s["to"]) <= TOL_S)
        if not check(same, "%s: step %d: expected %s %s %.1f-%.1f, azeltrack %s %s %.1f-%.1f" %
                     (sc["name"], k, e["kind"], want_norad, e["from"], e["to"], s["kind"],
                      s["norad"], s["from"], s["to"])):
            return


class RuleCheck:
    """The documented rules, read from azeltrack's plan alone (with skyfield's passes)."""

    def __init__(self, sc, entries, passes, sky, steps, norads):
        self.sc, self.entries, self.passes, self.sky = sc, entries, passes, sky
        self.steps, self.norads = steps, norads
        self.prio_of = {n: i for i, n in enumerate(norads)}
        self.tracks = [s for s in steps if s["kind"] == "track"]
        self.ok_passes = worked(entries, passes, SPAN_S)
        self.stats = {"take_over": 0, "given_way_to_finish": 0, "finish_wait": 0, "resume": 0,
                      "park": sum(s["kind"] == "park" for s in steps),
                      "preposition": sum(s["kind"] == "preposition" for s in steps),
                      "tracks": len(self.tracks),
                      "below_min_el": len(passes) - len(self.ok_passes)}

    def fail(self, ok, what):
        return check(ok, "%s: %s" % (self.sc["name"], what))

    def pass_at(self, prio, t):
        """The worked pass of entry prio up at t (1 s of slack at its ends), or None."""
        for p in self.ok_passes:
            if p["prio"] == prio and p["aos"] - TOL_S <= t <= p["los"] + TOL_S:
                return p
        return None

    def tracked_at(self, t):
        for s in self.tracks:
            if s["from"] <= t < s["to"]:
                return s
        return None

    def run(self):
        self.tracks_see_their_satellite()
        self.switches()
        self.nothing_better_missed()
        self.prepositions_and_parks()
        return self.stats

    def tracks_see_their_satellite(self):
        for s in self.tracks:
            prio = self.prio_of[s["norad"]]
            p = self.pass_at(prio, s["from"])
            if not self.fail(p is not None and s["to"] <= p["los"] + TOL_S,
                             "track %s %.1f-%.1f is not inside a worked pass" %
                             (s["norad"], s["from"], s["to"])):
                continue
            t = s["from"] + 0.5
            while t < s["to"] - 0.5:
                self.fail(self.sky[prio].above(t) > 0.0,
                          "track %s: satellite below the horizon at +%.1f" % (s["norad"], t))
                t += 30.0
            self.fail(self.sky[prio].above(s["to"] - 0.5) > 0.0,
                      "track %s: below the horizon before its end" % s["norad"])

    def switches(self):
        """Where each track starts and ends, and why."""
        for k, s in enumerate(self.tracks):
            prio = self.prio_of[s["norad"]]
            p = self.pass_at(prio, s["from"])
            if p is None:
                continue
            prev = self.tracks[k - 1] if k > 0 else None
            at_aos = abs(s["from"] - p["aos"]) <= TOL_S
            after_prev = prev is not None and abs(prev["to"] - s["from"]) <= TOL_S
            self.fail(at_aos or after_prev or s["from"] <= TOL_S,
                      "track %s starts at %.1f: neither its AOS %.1f nor a switch" %
                      (s["norad"], s["from"], p["aos"]))
            ends_at_los = abs(s["to"] - p["los"]) <= TOL_S or s["to"] >= SPAN_S - TOL_S
            if not ends_at_los:
                self.taken_over(s, prio, self.tracks[k + 1] if k + 1 < len(self.tracks) else None)
            if not at_aos and after_prev and p["aos"] < prev["from"]:
                self.stats["resume"] += 1
            elif not at_aos and after_prev and self.prio_of[prev["norad"]] > prio:
                # A better pass rose while a lower one ran, and waited for its LOS.
                prev_pass = self.pass_at(self.prio_of[prev["norad"]], prev["from"])
                if prev_pass is not None and abs(prev["to"] - prev_pass["los"]) <= TOL_S:
                    self.stats["finish_wait"] += 1

    def taken_over(self, s, prio, nxt):
        """A track left before its LOS: a better "take_over" pass rose then, and the best pass
        up follows (that one, or a better "finish" pass that was waiting for the running one)."""
        if not self.fail(nxt is not None and abs(nxt["from"] - s["to"]) <= TOL_S,
                         "track %s ends at %.1f before its LOS and nothing follows" %
                         (s["norad"], s["to"])):
            return
        takers = [p for p in self.ok_passes if abs(p["aos"] - s["to"]) <= TOL_S and
                  p["prio"] < prio and self.entries[p["prio"]]["preempt"] == "take_over"]
        up = [p for p in self.ok_passes if p["aos"] - TOL_S <= s["to"] < p["los"] - TOL_S]
        q = self.prio_of[nxt["norad"]]
        self.fail(takers and q == min(p["prio"] for p in up),
                  "track %s interrupted at %.1f by %s: no take_over AOS then, or not the best "
                  "pass up" % (s["norad"], s["to"], nxt["norad"]))
        self.stats["take_over"] += 1
        if takers and q != takers[0]["prio"]:
            self.stats["given_way_to_finish"] += 1

    def nothing_better_missed(self, step_s=5.0):
        """At every instant, the best pass up is followed, or it is a "finish" pass waiting for
        a lower one that was running when it rose."""
        t = step_s / 2.0
        while t < SPAN_S:
            up = [p for p in self.ok_passes if p["aos"] + TOL_S < t < p["los"] - TOL_S]
            if up:
                best = min(up, key=lambda p: (p["prio"], p["aos"]))
                s = self.tracked_at(t)
                prio = None if s is None else self.prio_of[s["norad"]]
                if prio is None or prio > best["prio"]:
                    waiting = (s is not None and
                               self.entries[best["prio"]]["preempt"] == "finish" and
                               s["from"] <= best["aos"] + TOL_S)
                    self.fail(waiting, "at +%.1f %s is up and %s is followed" %
                              (t, self.norads[best["prio"]], None if s is None else s["norad"]))
            t += step_s

    def prepositions_and_parks(self):
        at, free = PARK, 0.0
        for k, s in enumerate(self.steps):
            if s["kind"] == "preposition":
                self.preposition(s, self.steps[k + 1] if k + 1 < len(self.steps) else None,
                                 at, free)
            elif s["kind"] == "park":
                self.fail(abs(s["from"] - free - RULES["idle_park_s"]) <= TOL_S,
                          "park at %.1f: not 10 min after the antenna was free (%.1f)" %
                          (s["from"], free))
                need = slew_s(at, PARK, AZ_RATE, EL_RATE, RULES["settle_s"])
                self.fail(abs(s["to"] - s["from"] - need) <= TOL_S,
                          "park at %.1f lasts %.1f s, the slew is %.1f s" %
                          (s["from"], s["to"] - s["from"], need))
                at = PARK
            elif s["kind"] == "track":
                prio = self.prio_of[s["norad"]]
                az, el = self.sky[prio].look(s["to"])
                at = (float(az), float(el))
            free = s["to"]

    def preposition(self, s, nxt, at, free):
        if not self.fail(nxt is not None and nxt["kind"] == "track" and
                         nxt["norad"] == s["norad"] and nxt["from"] == s["to"],
                         "preposition for %s at %.1f is not followed by its track" %
                         (s["norad"], s["from"])):
            return
        prio = self.prio_of[s["norad"]]
        p = self.pass_at(prio, s["to"])
        self.fail(p is not None and abs(p["aos"] - s["to"]) <= TOL_S,
                  "preposition for %s ends at %.1f, not at an AOS" % (s["norad"], s["to"]))
        az, el = self.sky[prio].look(s["to"])
        need = slew_s(at, (float(az), float(el)), AZ_RATE, EL_RATE, RULES["settle_s"])
        long_enough = s["to"] - s["from"] >= need - TOL_S
        self.fail(long_enough or abs(s["from"] - free) <= TOL_S,
                  "preposition for %s %.1f-%.1f: %.1f s, the slew from %s is %.1f s" %
                  (s["norad"], s["from"], s["to"], s["to"] - s["from"], at, need))


def scenario(azeltrack, sc, ts, sats, wgs84):
    t0 = ts.from_datetime(FROM)
    dut1_s = float(t0.dut1)
    site = wgs84.latlon(sc["lat"], sc["lon"], sc["alt_m"])
    entries = [{"min_el": m, "preempt": r} for _, m, r in sc["schedule"]]
    norads = [int(n) for n, _, _ in sc["schedule"]]
    sky, passes, worst = [], [], 0.0
    for prio, (norad, _, _) in enumerate(sc["schedule"]):
        sp = SkyPasses(ts, sats[norad], site, t0, SPAN_S, sc["mask"])
        found = sp.find()
        for p in found:
            check(abs(p["max_el"] - entries[prio]["min_el"]) > 0.05,
                  "%s %s: a pass peaks within 0.05 deg of min_el_deg: pick another fixture" %
                  (sc["name"], norad))
            passes.append(dict(p, prio=prio, sky=lambda t, sp=sp: tuple(map(float, sp.look(t)))))
        sky.append(sp)
        worst = max(worst, compare_passes(sc, norad, found,
                                          azeltrack_passes(azeltrack, sc, norad, dut1_s)))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "schedule.toml")
        with open(path, "w") as f:
            f.write(config_text(sc, dut1_s))
        out = json.loads(run([azeltrack, "schedule", "--config", path, "--tle", CATALOGUE,
                              "--from", FROM.strftime("%Y-%m-%dT%H:%M:%SZ"), "--hours",
                              repr(HOURS), "--json"]))
    steps = [dict(s, **{"from": seconds(s["from"]), "to": seconds(s["to"])}) for s in out["plan"]]
    compare_plans(sc, oracle_plan(entries, passes, RULES, SPAN_S, PARK), steps, norads)
    stats = RuleCheck(sc, entries, passes, sky, steps, norads).run()
    print("%s: %d passes (worst AOS/LOS difference %.3f s), %d steps: %s" %
          (sc["name"], len(passes), worst, len(steps), stats))
    return stats


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    from skyfield.api import EarthSatellite, load, wgs84

    started = time.monotonic()
    ts = load.timescale(builtin=True)
    with open(CATALOGUE) as f:
        lines = [line.rstrip("\n") for line in f if line.strip()]
    check(len(lines) == 60, "the catalogue holds %d lines, not 20 element sets" % len(lines))
    sats = {}
    for i in range(0, len(lines), 3):
        sat = EarthSatellite(lines[i + 1], lines[i + 2], lines[i], ts)
        sats[lines[i + 1][2:7].strip()] = sat
    total = {}
    for sc in SCENARIOS:
        for k, v in scenario(argv[1], sc, ts, sats, wgs84).items():
            total[k] = total.get(k, 0) + v
    for k in ("take_over", "given_way_to_finish", "finish_wait", "resume", "below_min_el",
              "park", "preposition"):
        check(total.get(k, 0) >= 1, "the scenarios never exercise %s" % k)
    print("%.1f s" % (time.monotonic() - started))
    for f in failures:
        print("FAIL:", f)
    print("schedule against skyfield:", "FAILED" if failures else "ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

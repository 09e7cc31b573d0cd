"""An independent satellite schedule: passes from skyfield, the plan from the documented rules.

Used by schedule_skyfield_test.py (and tests/data/sat/make_schedule_scenario.py uses the pass
search). Nothing here comes from azeltrack's code: the passes are skyfield's, refined here, and
the plan is docs/satellites.md "The schedule" written out again in Python.

The horizon is azeltrack's: the geometric elevation of (satellite - site) at t, no light time,
no refraction, no polar motion, against `[satellites] mask` (a flat mask here: one elevation).
That is how core/src/orbit/passes.cpp decides "above" (look angles from
core/src/orbit/look_angles.cpp: TEME turned by GMST 1982 into Earth-fixed, a WGS84 site), and
skyfield's (sat - wgs84.latlon(...)).at(t).altaz() with no temperature/pressure is the same
quantity. Times are seconds after the window's start on a uniform scale (TT - the window holds no
leap second, so UTC seconds too).
"""
import math

import numpy as np
from skyfield.nutationlib import iau2000b_radians

GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


class SkyPasses:
    """Passes of one satellite over [t0, t0 + span_s] above a flat horizon."""

    def __init__(self, ts, sat, site, t0, span_s, horizon_deg):
        self.ts, self.sat, self.site, self.t0 = ts, sat, site, t0
        self.span_s, self.horizon_deg = span_s, horizon_deg
        self.diff = sat - site

    def time(self, s):
        t = self.ts.tt_jd(self.t0.tt + np.asarray(s) / 86400.0)
        # The shorter nutation series (skyfield's documented speed-up): nutation turns the
        # satellite into the GCRS and the site back out of it, so it cancels in the altitude.
        t._nutation_angles_radians = iau2000b_radians(t)
        return t

    def look(self, s):
        """(az_deg, el_deg) at s seconds after t0."""
        alt, az, _ = self.diff.at(self.time(s)).altaz()
        return az.degrees, alt.degrees

    def above(self, s):
        return self.look(s)[1] - self.horizon_deg

    def crossing(self, inside, outside, tol_s):
        """Bisection between a time above the horizon and one below it."""
        while abs(outside - inside) > tol_s:
            mid = 0.5 * (inside + outside)
            if self.above(mid) > 0.0:
                inside = mid
            else:
                outside = mid
        return 0.5 * (inside + outside)

    def peak(self, a, b, tol_s=0.05):
        """Golden-section search for the highest elevation in [a, b]: (t_s, el_deg)."""
        x1, x2 = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
        f1, f2 = self.look(x1)[1], self.look(x2)[1]
        while b - a > tol_s:
            if f1 >= f2:
                b, x2, f2 = x2, x1, f1
                x1 = b - GOLDEN * (b - a)
                f1 = self.look(x1)[1]
            else:
                a, x1, f1 = x1, x2, f2
                x2 = a + GOLDEN * (b - a)
                f2 = self.look(x2)[1]
        t = 0.5 * (a + b)
        return t, float(self.look(t)[1])

    def edge(self, tca, guess, direction, tol_s):
        """The horizon crossing on one side of a culmination above the horizon: from skyfield's
        event time (or a guess) outward while still above, then bisection against the
        culmination; (the window's edge, True) when the satellite is still above there."""
        limit = 0.0 if direction < 0 else self.span_s
        inside = tca
        outside = min(max(guess, 0.0), self.span_s)
        if (outside - tca) * direction < 0.0:
            outside = tca
        while self.above(outside) > 0.0:
            if outside == limit:
                return limit, True
            inside = outside
            outside = min(max(outside + 10.0 * direction, 0.0), self.span_s)
        return self.crossing(inside, outside, tol_s), False

    def find(self, tol_s=0.02):
        """Every pass: find_events, refined; a dense scan adds any grazing pass it left out.
        Returns dicts {aos, los, max_el, tca, clipped_start, clipped_end}."""
        t1 = self.time(self.span_s)
        times, events = self.sat.find_events(self.site, self.t0, t1,
                                             altitude_degrees=self.horizon_deg)
        rel = [((t.tt - self.t0.tt) * 86400.0, int(e)) for t, e in zip(times, events)]
        found = []
        for k, (tca_guess, e) in enumerate(rel):
            if e != 1:
                continue  # passes are built around their culminations
            rise = rel[k - 1][0] if k > 0 and rel[k - 1][1] == 0 else None
            set_ = rel[k + 1][0] if k + 1 < len(rel) and rel[k + 1][1] == 2 else None
            p = self.around_peak(tca_guess, tol_s, rise, set_)
            if p is not None and not any(overlaps(p, q) for q in found):
                found.append(p)
        self.added_by_scan = 0
        for p in self.scan(tol_s, found):
            if not any(overlaps(p, q) for q in found):
                found.append(p)
                self.added_by_scan += 1
        return sorted(found, key=lambda p: p["aos"])

    def around_peak(self, tca_guess, tol_s, rise=None, set_=None):
        """The pass around a culmination: skyfield's rise and set times (when find_events gave
        them) or a walk from the culmination, then bisection to tol_s."""
        tca, max_el = self.peak(max(0.0, tca_guess - 120.0), min(self.span_s, tca_guess + 120.0))
        if max_el <= self.horizon_deg:
            return None
        aos, clipped_start = self.edge(tca, tca - 10.0 if rise is None else rise, -1, tol_s)
        los, clipped_end = self.edge(tca, tca + 10.0 if set_ is None else set_, +1, tol_s)
        if clipped_start or clipped_end:
            tca, max_el = self.peak(aos, los)  # the highest point inside the window
        return {"aos": aos, "los": los, "tca": tca, "max_el": max_el,
                "clipped_start": clipped_start, "clipped_end": clipped_end}

    def scan(self, tol_s, known, step_s=20.0):
        """Every local maximum of the elevation sampled each step_s that refines above the
        horizon (a completeness check on find_events for short grazing passes)."""
        s = np.arange(0.0, self.span_s + step_s, step_s)
        s[-1] = min(s[-1], self.span_s)
        el = self.look(s)[1]
        out = []
        for i in range(1, len(s) - 1):
            inside = any(p["aos"] <= s[i] <= p["los"] for p in known)
            if el[i] >= el[i - 1] and el[i] > el[i + 1] and not inside:
                out.append(self.around_peak(s[i], tol_s))
        for i in (0, len(s) - 1):  # passes cut by the window's edges
            if el[i] > self.horizon_deg and not any(p["aos"] <= s[i] <= p["los"] for p in known):
                out.append(self.around_peak(s[i], tol_s))
        return [p for p in out if p is not None]


def overlaps(p, q):
    return p["aos"] < q["los"] and q["aos"] < p["los"]


def slew_s(a, b, az_rate, el_rate, settle_s):
    """The documented lead time: the slower axis at full speed (azimuth the short way round),
    plus the settle time."""
    daz = abs((b[0] - a[0] + 180.0) % 360.0 - 180.0)
    del_ = abs(b[1] - a[1])
    return max(daz / az_rate, del_ / el_rate) + settle_s


# ---- The plan, from docs/satellites.md "The schedule" ------------------------------------------
#
# Each pass: {"prio", "aos", "los", "max_el", "sky"} where prio indexes the priority list (0 is
# the highest) and sky(t) gives (az, el) of the satellite at t. Each entry: {"min_el", "preempt"}.


def worked(entries, passes, span_s):
    """Passes whose highest point reaches their entry's minimum elevation, inside the window."""
    return [p for p in passes
            if p["max_el"] >= entries[p["prio"]]["min_el"] and p["los"] > 0.0
            and p["aos"] < span_s]


def tracks(entries, passes, span_s):
    """Which pass is followed when: [(pass, from, to)]. At every instant the station follows the
    best pass up, except that the pass it follows goes on to its LOS when the better pass's rule
    is "finish". The choice can only change at an AOS or a LOS."""
    instants = sorted({0.0} | {t for p in passes for t in (p["aos"], p["los"])
                               if 0.0 < t < span_s})
    running = None
    out = []
    for k, t in enumerate(instants):
        up = sorted((p for p in passes if p["aos"] <= t < p["los"]),
                    key=lambda p: (p["prio"], p["aos"]))
        if running is not None and running not in up:
            running = None
        best = up[0] if up else None
        if running is None or (best is not running and
                               entries[best["prio"]]["preempt"] == "take_over"):
            running = best
        elif best is not running:
            # The best one up waits (its rule is "finish"); a take_over pass between the two
            # still interrupts the running one, and then the best one up is followed.
            if any(entries[p["prio"]]["preempt"] == "take_over" and p["prio"] < running["prio"]
                   for p in up):
                running = best
        if running is None:
            continue
        end = instants[k + 1] if k + 1 < len(instants) else span_s
        if out and out[-1][0] is running and out[-1][2] == t:
            out[-1] = (running, out[-1][1], end)
        else:
            out.append((running, t, end))
    return out


class Walk:
    """Where the antenna is and from when it is free; the steps so far. Pre-positions start as
    late as the slew allows but not before the antenna is free; 10 idle minutes park it."""

    def __init__(self, rules, start_sky):
        self.rules, self.at, self.free_from, self.steps = rules, start_sky, 0.0, []

    def slew(self, a, b):
        r = self.rules
        return slew_s(a, b, r["az_rate"], r["el_rate"], r["settle_s"])

    def park(self):
        begin = self.free_from + self.rules["idle_park_s"]
        end = begin + self.slew(self.at, self.rules["park_sky"])
        self.steps.append({"kind": "park", "prio": None, "from": begin, "to": end})
        self.at, self.free_from = self.rules["park_sky"], end

    def track(self, p, begin, end):
        target = p["sky"](begin)
        lead = begin - self.slew(self.at, target)
        if lead - self.free_from >= self.rules["idle_park_s"]:
            self.park()
            lead = begin - self.slew(self.at, target)
        lead = max(lead, self.free_from)
        if lead < begin:
            self.steps.append({"kind": "preposition", "prio": p["prio"], "from": lead,
                               "to": begin})
        self.steps.append({"kind": "track", "prio": p["prio"], "from": begin, "to": end})
        self.at, self.free_from = p["sky"](end), end

    def finish(self, span_s):
        if span_s - self.free_from >= self.rules["idle_park_s"]:
            self.park()
        return self.steps


def plan(entries, passes, rules, span_s, start_sky):
    ok = worked(entries, passes, span_s)
    walk = Walk(rules, start_sky)
    for p, begin, end in tracks(entries, ok, span_s):
        walk.track(p, begin, end)
    return walk.finish(span_s)

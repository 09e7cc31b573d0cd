#!/usr/bin/python3
"""Writes the OMM fixtures of tests/app/element_sets_test.cpp from the TLEs below.

Run with Debian's python (python3-sgp4): /usr/bin/python3 tests/data/omm/make_fixtures.py
It writes, next to itself:
  catalogue.tle   the four objects as a three-line catalogue (checksums computed here)
  catalogue.xml   CCSDS NDM/XML as CelesTrak serves FORMAT=xml (one <omm> per object)
  catalogue.json  CelesTrak FORMAT=json: an array of flat objects, numbers as JSON numbers
  catalogue.kvn   CCSDS KVN, the objects concatenated, each starting with CCSDS_OMM_VERS
  catalogue.csv   CelesTrak FORMAT=csv

The numbers are written as the TLE prints them (the implied-decimal fields as plain decimals, as
CelesTrak does), and the epoch is python3-sgp4's own conversion of the TLE epoch
(sgp4.conveniences.sat_epoch_datetime, microseconds). As an oracle check, each file is read back
with sgp4.omm (parse_xml, parse_csv, initialize; json and a small KVN reader here) and must
propagate to the same position as the TLE (Satrec.twoline2rv) over two days, within 1 cm.
"""

import csv
import io
import json
import os
from decimal import Decimal

from sgp4 import omm
from sgp4.api import Satrec
from sgp4.conveniences import sat_epoch_datetime
from sgp4.io import compute_checksum

HERE = os.path.dirname(os.path.abspath(__file__))

# Element sets shaped like CelesTrak's of March 2024 (near-Earth LEO, polar, Molniya deep space,
# a decaying object with a non-zero n-double-dot and a negative B*). Checksums are recomputed.
TLES = [
    ("ISS (ZARYA)",
     "1 25544U 98067A   24061.52430556  .00016717  00000-0  30015-3 0  999",
     "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.49815361441725"),
    ("NOAA 19",
     "1 33591U 09005A   24061.48091435  .00000227  00000-0  14581-3 0  999",
     "2 33591  99.1923 110.7368 0013513 293.6093  66.3646 14.12720431779541"),
    ("MOLNIYA 2-9",
     "1 07276U 74026A   24060.91744655 -.00000115  00000-0  00000+0 0  999",
     "2 07276  64.1523 171.2340 6717043 286.8839  13.5436  2.00607523234567"),
    ("DEBRIS 2024",
     "1 58001U 23185D   24061.00001157  .01234567  13844-5 -11606-4 0  123",
     "2 58001  97.4021   0.0000 0012345   0.0001 359.9999 16.12345678  1012"),
]

FIELDS = ["OBJECT_NAME", "OBJECT_ID", "EPOCH", "MEAN_MOTION", "ECCENTRICITY", "INCLINATION",
          "RA_OF_ASC_NODE", "ARG_OF_PERICENTER", "MEAN_ANOMALY", "EPHEMERIS_TYPE",
          "CLASSIFICATION_TYPE", "NORAD_CAT_ID", "ELEMENT_SET_NO", "REV_AT_EPOCH", "BSTAR",
          "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT"]
METADATA = ["OBJECT_NAME", "OBJECT_ID"]
MEAN_ELEMENTS = ["EPOCH", "MEAN_MOTION", "ECCENTRICITY", "INCLINATION", "RA_OF_ASC_NODE",
                 "ARG_OF_PERICENTER", "MEAN_ANOMALY"]
TLE_PARAMETERS = ["EPHEMERIS_TYPE", "CLASSIFICATION_TYPE", "NORAD_CAT_ID", "ELEMENT_SET_NO",
                  "REV_AT_EPOCH", "BSTAR", "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT"]


def with_checksum(line):
    """Columns 1-68 as written above, then the mod-10 checksum in column 69."""
    line = line[:68]
    assert len(line) == 68, line
    return line + str(compute_checksum(line))


def implied(field):
    """' 30015-3' -> Decimal('0.30015e-3')."""
    sign = "-" if field[0] == "-" else ""
    return Decimal(sign + "0." + field[1:6] + "e" + field[6:8].replace(" ", "+"))


def plain(d):
    """A Decimal as the shortest text that reads back as the same double (CelesTrak's style)."""
    return repr(float(d))


def fields_of(name, line1, line2):
    sat = Satrec.twoline2rv(line1, line2)
    year = int(line1[9:11])
    year += 1900 + (year < 57) * 100
    return {
        "OBJECT_NAME": name,
        "OBJECT_ID": "%d-%s" % (year, line1[11:17].strip()),
        "EPOCH": sat_epoch_datetime(sat).strftime("%Y-%m-%dT%H:%M:%S.%f"),
        "MEAN_MOTION": plain(Decimal(line2[52:63])),
        "ECCENTRICITY": plain(Decimal("0." + line2[26:33])),
        "INCLINATION": plain(Decimal(line2[8:16])),
        "RA_OF_ASC_NODE": plain(Decimal(line2[17:25])),
        "ARG_OF_PERICENTER": plain(Decimal(line2[34:42])),
        "MEAN_ANOMALY": plain(Decimal(line2[43:51])),
        "EPHEMERIS_TYPE": "0",
        "CLASSIFICATION_TYPE": line1[7],
        "NORAD_CAT_ID": str(int(line1[2:7])),
        "ELEMENT_SET_NO": str(int(line1[64:68])),
        "REV_AT_EPOCH": str(int(line2[63:68])),
        "BSTAR": plain(implied(line1[53:61])),
        "MEAN_MOTION_DOT": plain(Decimal(line1[33:43])),
        "MEAN_MOTION_DDOT": plain(implied(line1[44:52])),
    }


def write_xml(objects):
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           '<ndm xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
           'xsi:noNamespaceSchemaLocation="https://sanaregistry.org/r/ndmxml_unqualified/'
           'ndmxml-2.0.0-master-2.0.xsd">']
    for f in objects:
        out.append('<omm id="CCSDS_OMM_VERS" version="2.0">')
        out.append("<header><CREATION_DATE/><ORIGINATOR/></header>")
        out.append("<body><segment><metadata>")
        meta = [(k, f[k]) for k in METADATA] + [
            ("CENTER_NAME", "EARTH"), ("REF_FRAME", "TEME"), ("TIME_SYSTEM", "UTC"),
            ("MEAN_ELEMENT_THEORY", "SGP4")]
        out += ["<%s>%s</%s>" % (k, v.replace("&", "&amp;"), k) for k, v in meta]
        out.append("</metadata><data><meanElements>")
        out += ["<%s>%s</%s>" % (k, f[k], k) for k in MEAN_ELEMENTS]
        out.append("</meanElements><tleParameters>")
        out += ["<%s>%s</%s>" % (k, f[k], k) for k in TLE_PARAMETERS]
        out.append("</tleParameters></data></segment></body></omm>")
    out.append("</ndm>")
    return "\n".join(out) + "\n"


def write_json(objects):
    numeric = set(MEAN_ELEMENTS[1:] + ["BSTAR", "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT"])
    integer = {"EPHEMERIS_TYPE", "NORAD_CAT_ID", "ELEMENT_SET_NO", "REV_AT_EPOCH"}
    rows = []
    for f in objects:
        row = {}
        for k in FIELDS:
            row[k] = float(f[k]) if k in numeric else int(f[k]) if k in integer else f[k]
        rows.append(row)
    return json.dumps(rows, indent=1) + "\n"


def write_kvn(objects):
    out = []
    for f in objects:
        out += ["CCSDS_OMM_VERS = 2.0", "CREATION_DATE = 2024-03-01T14:00:00",
                "ORIGINATOR = CELESTRAK", "",
                "OBJECT_NAME = " + f["OBJECT_NAME"], "OBJECT_ID = " + f["OBJECT_ID"],
                "CENTER_NAME = EARTH", "REF_FRAME = TEME", "TIME_SYSTEM = UTC",
                "MEAN_ELEMENT_THEORY = SGP4", ""]
        out += ["%s = %s" % (k, f[k]) for k in MEAN_ELEMENTS]
        out += ["%s = %s" % (k, f[k]) for k in TLE_PARAMETERS]
        out.append("")
    return "\n".join(out)


def write_csv(objects):
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=FIELDS, lineterminator="\r\n")
    writer.writeheader()
    writer.writerows(objects)
    return text.getvalue()


def read_kvn(text):
    objects = []
    for line in text.splitlines():
        if line.startswith("CCSDS_OMM_VERS"):
            objects.append({})
        elif "=" in line:
            key, value = line.split("=", 1)
            objects[-1][key.strip()] = value.strip()
    return objects


def check(name, fields, line1, line2):
    """sgp4.omm.initialize on the file's fields must propagate like the TLE."""
    want = Satrec.twoline2rv(line1, line2)
    got = Satrec()
    omm.initialize(got, {k: str(v) for k, v in fields.items()})
    for minutes in (0.0, 720.0, 2880.0):
        jd = want.jdsatepoch + want.jdsatepochF + minutes / 1440.0
        e1, r1, _ = want.sgp4(jd, 0.0)
        e2, r2, _ = got.sgp4(jd, 0.0)
        assert e1 == e2 == 0, (name, e1, e2)
        # 1 cm: the OMM epoch keeps whole microseconds (sat_epoch_datetime truncates), 8 mm at
        # 7.7 km/s; everything else is the same double.
        assert max(abs(a - b) for a, b in zip(r1, r2)) < 1e-5, (name, r1, r2)


def main():
    tles = [(n, with_checksum(l1), with_checksum(l2)) for n, l1, l2 in TLES]
    objects = [fields_of(*t) for t in tles]
    files = {
        "catalogue.tle": "".join("%s\n%s\n%s\n" % t for t in tles),
        "catalogue.xml": write_xml(objects),
        "catalogue.json": write_json(objects),
        "catalogue.kvn": write_kvn(objects),
        "catalogue.csv": write_csv(objects),
    }
    for name, text in files.items():
        with open(os.path.join(HERE, name), "w", newline="") as f:
            f.write(text)
    readers = {
        "catalogue.xml": lambda: list(omm.parse_xml(os.path.join(HERE, "catalogue.xml"))),
        "catalogue.csv": lambda: list(omm.parse_csv(io.StringIO(files["catalogue.csv"]))),
        "catalogue.json": lambda: json.loads(files["catalogue.json"]),
        "catalogue.kvn": lambda: read_kvn(files["catalogue.kvn"]),
    }
    for name, read in readers.items():
        parsed = read()
        assert len(parsed) == len(tles), name
        for fields, (object_name, l1, l2) in zip(parsed, tles):
            check(name + ": " + object_name, fields, l1, l2)
    print("wrote and checked", ", ".join(files))


if __name__ == "__main__":
    main()

"""Two-line element text from numbers: fixed columns and the modulo-10 checksum.

Shared by the generators in this folder (make_schedule_catalogue.py, make_schedule_scenario.py).
The columns are those of the TLE format as CelesTrak documents it; the checksum is the sum of the
digits with 1 for each '-', modulo 10, in column 69.
"""


def checksum(line68):
    """The checksum digit of the first 68 columns."""
    total = 0
    for c in line68[:68]:
        if c.isdigit():
            total += int(c)
        elif c == "-":
            total += 1
    return str(total % 10)


def with_checksum(line68):
    line68 = line68[:68].ljust(68)
    return line68 + checksum(line68)


def element_lines(norad, intl, epoch, ndot, nddot, bstar, incl, raan, ecc, argp, ma, n, rev=1):
    """Line 1 and line 2 of one element set.

    epoch: "YYDDD.DDDDDDDD" (14 characters); ndot, nddot, bstar: the fields as a TLE prints them
    (10, 8 and 8 characters, e.g. " .00016717", " 00000-0", " 30119-3"); angles in degrees,
    ecc as a fraction, n in revolutions per day.
    """
    assert len(epoch) == 14 and len(ndot) == 10 and len(nddot) == 8 and len(bstar) == 8
    assert 0.0 <= ecc < 1.0
    ecc_digits = "%07d" % round(ecc * 1e7)
    line1 = "1 %05dU %-8s %s %s %s %s 0  999" % (norad, intl, epoch, ndot, nddot, bstar)
    line2 = "2 %05d %8.4f %8.4f %s %8.4f %8.4f %11.8f%5d" % (
        norad, incl, raan % 360.0, ecc_digits, argp % 360.0,
        ma % 360.0, n, rev % 100000)
    assert len(line1) == 68 and len(line2) == 68, (line1, line2)
    return with_checksum(line1), with_checksum(line2)

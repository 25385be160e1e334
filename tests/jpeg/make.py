#!/usr/bin/python3
"""Writes the JPEG golden files of tests/jpeg/ (run once, committed; the
test does not run this).  Debian's OpenCV (libjpeg-turbo) encodes an
asymmetric, coloured 24x16 image in the variants glscene must decode, and
decodes each back to a PNG: the unit test (tests/unit/test_compile.c)
compares glscene's decoding with it.  It then derives from them the files
that made Debian's stb_image misbehave (tests/fuzz/README.md, finding
10), which glscene must refuse or decode the same on every run.

    /usr/bin/python3 tests/jpeg/make.py tests/jpeg
"""
import os
import sys

import cv2
import numpy as np

out = sys.argv[1]
h, w = 16, 24
y, x = np.mgrid[0:h, 0:w]
# BGR (OpenCV's order): a red ramp left to right, a green ramp top to
# bottom, a blue square in the top-left corner and a white bar at the
# bottom right, so flips, transposes and channel swaps all show
img = np.zeros((h, w, 3), np.uint8)
img[..., 2] = (x * 255 // (w - 1)).astype(np.uint8)
img[..., 1] = (y * 255 // (h - 1)).astype(np.uint8)
img[2:8, 2:8] = (255, 40, 0)
img[12:15, 14:22] = (255, 255, 255)
grey = cv2.cvtColor(img, cv2.COLOR_BGR2GRAY)

Q = cv2.IMWRITE_JPEG_QUALITY
variants = {
    "baseline": (img, [Q, 95]),
    "grey": (grey, [Q, 95]),
    "progressive": (img, [Q, 95, cv2.IMWRITE_JPEG_PROGRESSIVE, 1]),
    "progressive_grey": (grey, [Q, 95, cv2.IMWRITE_JPEG_PROGRESSIVE, 1]),
    "restart": (img, [Q, 95, cv2.IMWRITE_JPEG_RST_INTERVAL, 1]),
    "optimized": (img, [Q, 60, cv2.IMWRITE_JPEG_OPTIMIZE, 1]),
}
files = {}
for name, (im, params) in variants.items():
    ok, buf = cv2.imencode(".jpg", im, params)
    assert ok
    files[name] = bytes(buf)
    with open(os.path.join(out, name + ".jpg"), "wb") as f:
        f.write(files[name])
    dec = cv2.imdecode(np.frombuffer(files[name], np.uint8), cv2.IMREAD_COLOR)
    cv2.imwrite(os.path.join(out, name + ".decoded.png"), dec)


def segments(b):
    """(offset, marker) of each marker segment before the first scan's data"""
    p, found = 2, []
    while True:
        assert b[p] == 0xFF
        m = b[p + 1]
        found.append((p, m))
        if m == 0xDA:
            return found
        p += 2 + (b[p + 2] << 8 | b[p + 3])


def must_fail(name, data):
    cv_ok = cv2.imdecode(np.frombuffer(bytes(data), np.uint8), cv2.IMREAD_UNCHANGED) is not None
    print(f"{name}: libjpeg-turbo {'decodes it (with a warning)' if cv_ok else 'refuses it'}")
    with open(os.path.join(out, name + ".jpg"), "wb") as f:
        f.write(bytes(data))


g = bytearray(files["grey"])
sos = [p for p, m in segments(g) if m == 0xDA][0]
sof = [p for p, m in segments(g) if m == 0xC0][0]
# the scan decodes with DC and AC Huffman tables 1, never defined
b = bytearray(g)
b[sos + 6] = 0x11
must_fail("bad_undefined_huffman", b)
# the component uses quantisation table 1, never defined
b = bytearray(g)
b[sof + 12] = 1
must_fail("bad_undefined_quant", b)
# a Huffman table declares more than 256 codes (stb_image wrote past a
# table: finding 3)
b = bytearray(g)
dht = [p for p, m in segments(g) if m == 0xC4][0]
b[dht + 5 + 15] = 250
must_fail("bad_huffman_overflow", b)
# the file stops in the middle of its scan
must_fail("bad_truncated", files["baseline"][: len(files["baseline"]) * 2 // 3])
# the frame has three components, the only scan codes the first: not a
# file to refuse (libjpeg-turbo decodes the chroma it never read as
# neutral), but Debian's stb_image decoded memory it never wrote
b = bytearray(g)
comps = bytes([2, 0x11, 0, 3, 0x11, 0])
b[sof + 9] = 3
b[sof + 2: sof + 4] = (8 + 3 * 3).to_bytes(2, "big")  # Lf = 8 + 3 Nf
b[sof + 13: sof + 13] = comps
with open(os.path.join(out, "component_in_no_scan.jpg"), "wb") as f:
    f.write(bytes(b))

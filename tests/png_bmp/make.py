#!/usr/bin/python3
"""Writes the PNG and BMP golden files of tests/png_bmp/ (run once,
committed; the test does not run this).  Debian's OpenCV (libpng, and its
own BMP writer) stores an asymmetric, coloured 24x16 image with a
transparent corner in each channel layout and depth it writes, and this
script writes beside each the RGBA8 texels glscene must decode it to, as
raw bytes (NAME.rgba: row 0 at the top, 4 bytes a texel), computed here
with numpy, not by any decoder: 16-bit samples keep their high byte,
grey is copied to R, G and B, a missing alpha is 255, and alpha is then
made binary (255 from 128 up, else 0; spec/language.md 2.2).

    /usr/bin/python3 tests/png_bmp/make.py tests/png_bmp
"""
import os
import sys

import cv2
import numpy as np

out = sys.argv[1]
h, w = 16, 24
y, x = np.mgrid[0:h, 0:w]
# 16-bit RGB: ramps whose low bytes differ from their high bytes, so
# that keeping the wrong byte shows
r = (x * 65535 // (w - 1)).astype(np.uint16)
g = (y * 65535 // (h - 1)).astype(np.uint16)
b = ((x * 7 + y * 13) % 256 * 257 + (x % 3)).astype(np.uint16)
a = np.full((h, w), 65535, np.uint16)
b[2:8, 2:8] = 65535  # a blue square at the top left
r[2:8, 2:8] = g[2:8, 2:8] = 0
a[0:4, 18:24] = 0  # transparent at the top right
a[12:16, 0:6] = 32767  # high byte 127, low 255: transparent (rounding would make it 128)
a[12:16, 6:12] = 128 * 257  # half: opaque
rgba16 = np.dstack([r, g, b, a])
grey16 = ((r.astype(np.uint32) * 3 + g * 5 + b * 2) // 10).astype(np.uint16)


def expected(rgba8):
    e = rgba8.copy()
    e[..., 3] = np.where(e[..., 3] >= 128, 255, 0)
    return e


def write(name, bgr_image, rgba8):
    ok = cv2.imwrite(os.path.join(out, name), bgr_image)
    assert ok, name
    with open(os.path.join(out, os.path.splitext(name)[0] + ".rgba"), "wb") as f:
        f.write(expected(rgba8).astype(np.uint8).tobytes())


hi = lambda v: (v >> 8).astype(np.uint8)
rgba8 = hi(rgba16)
opaque = rgba8.copy()
opaque[..., 3] = 255
g8 = hi(grey16)
grey_rgba = np.dstack([g8, g8, g8, np.full((h, w), 255, np.uint8)])
bgr = lambda im: im[..., [2, 1, 0]]
bgra = lambda im: im[..., [2, 1, 0, 3]]

write("rgba8.png", bgra(rgba8), rgba8)
write("rgb8.png", bgr(rgba8), opaque)
write("grey8.png", g8, grey_rgba)
write("rgba16.png", bgra(rgba16), rgba8)
write("rgb16.png", bgr(rgba16), opaque)
write("grey16.png", grey16, grey_rgba)
write("rgb24.bmp", bgr(rgba8), opaque)
write("grey8.bmp", g8, grey_rgba)  # OpenCV writes it with a grey palette

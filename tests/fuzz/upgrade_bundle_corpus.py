#!/usr/bin/python3
"""Carry the bundle fuzz corpus from format version 1 to 2 (issue 14), in
place: usage /usr/bin/python3 tests/fuzz/upgrade_bundle_corpus.py DIR...

Each input whose version-1 directory is intact gets one more directory
entry, an empty TEMPLATES section (raw, 4 zero bytes) at the end, the
offsets shifted, size and CRC fixed.  Other version-1 inputs (a damaged
directory) keep their bytes but for the version field.  The reader refuses
version 1 at once (spec/bundle.md 4.2), so without this the inputs the
fuzzer found would only reach that check.  Deterministic: the same corpus
gives the same bytes.  Run once when the format went to 2; the corpus was
then minimised with libFuzzer's -merge=1 (tests/fuzz/README.md)."""
import os, struct, sys, zlib

def convert(b):
    if len(b) < 240 or b[:8] != b"\x89GLS\r\n\x1a\n" or struct.unpack_from("<I", b, 8)[0] != 1:
        return None
    entries = [list(struct.unpack_from("<IIQQQ", b, 48 + 32 * i)) for i in range(6)]
    off = 240
    for e in entries:
        if e[2] != off or e[2] + e[3] > len(b):
            return bytearray(b[:8] + struct.pack("<I", 2) + b[12:])
        off = e[2] + e[3]
    body = b[240:off]
    for e in entries:
        e[2] += 32
    entries.append([7, 0, off + 32, 4, 4])
    out = bytearray(b[:48])
    struct.pack_into("<I", out, 8, 2)
    struct.pack_into("<I", out, 24, 7)
    for e in entries:
        out += struct.pack("<IIQQQ", *e)
    out += body + b"\0\0\0\0" + b[off:]
    struct.pack_into("<Q", out, 32, len(out))
    struct.pack_into("<I", out, 40, 0)
    struct.pack_into("<I", out, 40, zlib.crc32(bytes(out)) & 0xffffffff)
    return out

n = 0
for d in sys.argv[1:]:
    for f in sorted(os.listdir(d)):
        p = os.path.join(d, f)
        b = open(p, "rb").read()
        c = convert(b)
        if c is not None:
            open(p, "wb").write(c)
            n += 1
print("converted", n)

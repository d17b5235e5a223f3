#!/usr/bin/env python3
"""Converts capi-test images (TESSIMG header + raw samples, rows bottom-up) to PNG.

Usage: tools/img2png.py IMAGE.img [OUT.png] [--scale N]
Only u8 images with 3 or 4 channels are converted (enough to look at them).
"""
import struct, sys, zlib

def load(path):
    data = open(path, "rb").read()
    nl = data.index(b"\n")
    _, w, h, channels, kind = data[:nl].split()
    return int(w), int(h), int(channels), kind.decode(), data[nl + 1:]

def write_png(path, w, h, rows):
    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + row for row in rows)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)

def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    scale = int(sys.argv[sys.argv.index("--scale") + 1]) if "--scale" in sys.argv else 1
    args = [a for a in args if not (a.isdigit() and "--scale" in sys.argv)]
    src = args[0]
    out = args[1] if len(args) > 1 else src.rsplit(".", 1)[0] + ".png"
    w, h, channels, kind, px = load(src)
    assert kind == "u8" and channels in (3, 4), "only u8 RGB(A) images"
    rows = []
    for y in range(h - 1, -1, -1):
        row = bytearray()
        for x in range(w):
            i = (y * w + x) * channels
            row += px[i:i + 3] * 1 if scale == 1 else b"".join([px[i:i + 3]] * scale)
        rows.extend([bytes(row)] * scale)
    write_png(out, w * scale, h * scale, rows)
    print(out)

main()

#!/usr/bin/env python3
"""Checks a window screenshot in XWD format (from `xwd -silent`) without other tools.

Usage:
  xwd_check.py FILE not-blank              the picture has at least 2 colors, and at least
                                           1% of the pixels differ from the most common one
  xwd_check.py FILE pixel X Y R G B [TOL]  ... (repeatable groups: pixel X Y R G B TOL)
                                           pixel (X, Y) (top-left origin) is R,G,B within TOL
Exit status 0 when every check holds; prints what it saw.
"""
import struct
import sys
from collections import Counter


def read_xwd(path):
    data = open(path, "rb").read()
    # The header is 25 big-endian 32-bit fields (xwd swaps it to MSB first).
    fields = struct.unpack(">25I", data[:100])
    header_size, _version, _format, _depth, width, height = fields[:6]
    byte_order, bits_per_pixel, bytes_per_line = fields[7], fields[11], fields[12]
    masks = fields[14:17]
    ncolors = fields[19]
    offset = header_size + ncolors * 12
    if bits_per_pixel not in (24, 32):
        sys.exit(f"xwd_check: {bits_per_pixel} bits per pixel not handled")
    bpp = bits_per_pixel // 8
    endian = "little" if byte_order == 0 else "big"

    def channel(value, mask):
        shift = (mask & -mask).bit_length() - 1
        return (value & mask) >> shift

    def pixel(x, y):
        start = offset + y * bytes_per_line + x * bpp
        value = int.from_bytes(data[start:start + bpp], endian)
        return tuple(channel(value, m) for m in masks)

    return width, height, pixel


def main():
    path, args = sys.argv[1], sys.argv[2:]
    width, height, pixel = read_xwd(path)
    ok = True
    while args:
        check = args.pop(0)
        if check == "not-blank":
            counts = Counter(pixel(x, y) for y in range(0, height, 2) for x in range(0, width, 2))
            common, n = counts.most_common(1)[0]
            total = sum(counts.values())
            other = total - n
            print(f"xwd_check: {width}x{height}, {len(counts)} colors, {other}/{total} samples differ from {common}")
            ok &= len(counts) >= 2 and other * 100 >= total
        elif check == "pixel":
            x, y, r, g, b, tol = (int(v) for v in args[:6])
            del args[:6]
            got = pixel(x, y)
            good = all(abs(a - e) <= tol for a, e in zip(got, (r, g, b)))
            print(f"xwd_check: pixel ({x},{y}) = {got}, want {(r, g, b)} +-{tol}: {'ok' if good else 'WRONG'}")
            ok &= good
        else:
            sys.exit(f"xwd_check: unknown check {check}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()

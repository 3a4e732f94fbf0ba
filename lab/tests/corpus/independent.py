#!/usr/bin/env python3
"""Pixel values of camera.png worked out independently of the `image` crate
and of the core: a plain PNG decoder (zlib + the five scanline filters, 8-bit
grey, not interlaced) and the 3×3 mean and Sobel sums written out by hand.
The numbers printed are the ones `tests/operators.rs` checks.

    python3 lab/tests/corpus/independent.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, w = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 0, 0), (depth, colour, interlace)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    rows, prev = [], bytes(w)
    for r in range(h):
        f, line = raw[r * (w + 1)], bytearray(raw[r * (w + 1) + 1:(r + 1) * (w + 1)])
        for i in range(w):
            a = line[i - 1] if i else 0
            b, c = prev[i], prev[i - 1] if i else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(bytes(line))
        prev = line
    return rows


def main():
    g = read_png(os.path.join(HERE, "../../../www/lab/samples/camera.png"))
    for c, r in [(0, 0), (100, 50), (256, 256), (300, 400), (511, 511)]:
        grey = g[r][c]
        mean = sum(g[r + j][c + i] for j in (-1, 0, 1) for i in (-1, 0, 1)) / 9 if 0 < c < 511 and 0 < r < 511 else None
        gx = sum(k * g[r - 1][c + i] for i, k in zip((-1, 0, 1), (1, 2, 1))) - sum(k * g[r + 1][c + i] for i, k in zip((-1, 0, 1), (1, 2, 1))) if mean is not None else None
        print(f"({c}, {r}): grey {grey}, 3×3 mean {mean!r}, Sobel gx {gx}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes the decode corpus of the lab's tests (standard library only).

Good files with known pixel values: grey 8-bit PNG, grey 16-bit PNG, RGB PNG,
TIFF 8-bit grey (strips), TIFF 16-bit grey (strips), TIFF 8-bit RGB (tiles),
TIFF 16-bit RGB (strips), TIFF 8-bit and 16-bit grey in several tiles,
TIFF 8-bit grey compressed with Deflate; and a GIF, a format the lab does
not read. The JPEGs are written by the lab's ignored test
`write_jpegs` (flat 8×8 blocks, which baseline JPEG stores exactly).
Bad files: truncated PNG, PNG with a wrong CRC, zero-width PNG, a PNG header
claiming 100000×100000, a decompression bomb (5000×5000 zeros in a few kB),
a TIFF without its StripOffsets tag, a text file named .png, an empty file.
The truncated JPEG is written by `write_jpegs` too.

    python3 lab/tests/corpus/make_corpus.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def chunk(kind, data, crc=None):
    c = zlib.crc32(kind + data) if crc is None else crc
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", c & 0xFFFFFFFF)


def png(width, height, bit_depth, colour_type, rows, bad_crc=False, level=9):
    """rows: list of bytes (already packed samples, big-endian for 16 bit)."""
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    raw = b"".join(b"\x00" + r for r in rows)
    idat = zlib.compress(raw, level)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
    out += chunk(b"IDAT", idat, crc=0x12345678 if bad_crc else None)
    return out + chunk(b"IEND", b"")


# Known pixels: grey(c, r) = 10·c + 40·r (4 × 3 image).
def grey8(c, r):
    return 10 * c + 40 * r


def grey16(c, r):
    return 1000 * c + 20000 * r + 7  # uses the full 16 bits (up to 46007)


def rgb8(c, r):
    return (50 * c, 60 * r, 200 - 30 * c)


def rgb16(c, r):
    return (10000 * c + 1, 15000 * r + 2, 60000 - 9000 * c)


W, H = 4, 3

# The multi-tile and compressed TIFFs: 40 × 24 pixels.
TW, TH = 40, 24


def tile8(c, r):
    return (7 * c + 11 * r) % 256


def tile16(c, r):
    return 1000 * c + 1000 * r + 7  # up to 62007, not multiples of 257


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def tiff(width, height, spp, bps, pixel_bytes, tiles=None, drop_tag=None, deflate=False):
    """Little-endian baseline TIFF, uncompressed (or each strip or tile
    zlib-compressed: `deflate`, compression 8); strips (one per row) or
    tiles (tile size `tiles`, padded)."""
    entries = []

    def tag(t, typ, count, value):
        entries.append((t, typ, count, value))

    data_blobs = []
    if tiles:
        tw, th = tiles
        across, down = (width + tw - 1) // tw, (height + th - 1) // th
        for ty in range(down):
            for tx in range(across):
                blob = b""
                for r in range(ty * th, ty * th + th):
                    for c in range(tx * tw, tx * tw + tw):
                        if r < height and c < width:
                            blob += pixel_bytes(c, r)
                        else:
                            blob += b"\x00" * (spp * bps // 8)
                data_blobs.append(blob)
    else:
        for r in range(height):
            data_blobs.append(b"".join(pixel_bytes(c, r) for c in range(width)))
    if deflate:
        data_blobs = [zlib.compress(b, 9) for b in data_blobs]
    # layout: header(8) | blobs | bits-per-sample array | offsets | counts | IFD
    offset = 8
    offs = []
    for b in data_blobs:
        offs.append(offset)
        offset += len(b)
    bps_off = offset
    bps_arr = struct.pack("<" + "H" * spp, *([bps] * spp))
    offset += len(bps_arr)
    offs_off = offset
    offs_arr = struct.pack("<" + "I" * len(offs), *offs)
    offset += len(offs_arr)
    cnt_off = offset
    cnt_arr = struct.pack("<" + "I" * len(data_blobs), *[len(b) for b in data_blobs])
    offset += len(cnt_arr)
    ifd_off = offset
    n = len(data_blobs)

    def arr_or_inline(typ, values, where):
        if len(values) == 1:
            return (typ, 1, values[0])
        return (typ, len(values), where)

    tag(256, 4, 1, width)
    tag(257, 4, 1, height)
    t = arr_or_inline(3, [bps] * spp, bps_off)
    if spp == 1:
        tag(258, 3, 1, bps)
    else:
        tag(258, 3, spp, bps_off)
    tag(259, 3, 1, 8 if deflate else 1)  # Deflate or no compression
    tag(262, 3, 1, 1 if spp == 1 else 2)  # BlackIsZero / RGB
    if tiles:
        tag(322, 4, 1, tiles[0])
        tag(323, 4, 1, tiles[1])
        tag(324, 4, n, offs_off if n > 1 else offs[0])
        tag(325, 4, n, cnt_off if n > 1 else len(data_blobs[0]))
    else:
        tag(273, 4, n, offs_off if n > 1 else offs[0])
        tag(278, 4, 1, 1)  # rows per strip
        tag(279, 4, n, cnt_off if n > 1 else len(data_blobs[0]))
    tag(277, 3, 1, spp)
    tag(284, 3, 1, 1)  # chunky
    entries.sort()
    if drop_tag is not None:
        entries = [e for e in entries if e[0] != drop_tag]
    ifd = struct.pack("<H", len(entries))
    for t_, typ, count, value in entries:
        if typ == 3 and count == 1:
            ifd += struct.pack("<HHIHH", t_, typ, count, value, 0)
        else:
            ifd += struct.pack("<HHII", t_, typ, count, value)
    ifd += struct.pack("<I", 0)
    head = b"II" + struct.pack("<HI", 42, ifd_off)
    return head + b"".join(data_blobs) + bps_arr + offs_arr + cnt_arr + ifd


def main():
    # good PNGs
    write("grey8.png", png(W, H, 8, 0, [bytes(grey8(c, r) for c in range(W)) for r in range(H)]))
    write("grey16.png", png(W, H, 16, 0,
                            [b"".join(struct.pack(">H", grey16(c, r)) for c in range(W)) for r in range(H)]))
    write("rgb8.png", png(W, H, 8, 2, [bytes(v for c in range(W) for v in rgb8(c, r)) for r in range(H)]))
    # good TIFFs
    write("grey8_strips.tif", tiff(W, H, 1, 8, lambda c, r: bytes([grey8(c, r)])))
    write("grey16_strips.tif", tiff(W, H, 1, 16, lambda c, r: struct.pack("<H", grey16(c, r))))
    write("rgb8_tiles.tif", tiff(W, H, 3, 8, lambda c, r: bytes(rgb8(c, r)), tiles=(16, 16)))
    write("rgb16_strips.tif", tiff(W, H, 3, 16, lambda c, r: struct.pack("<HHH", *rgb16(c, r))))
    # several tiles: 40 × 24 pixels in 16 × 16 tiles (3 × 2 tiles, the
    # right and bottom ones padded); 8-bit and 16-bit grey
    write("grey8_tiles.tif", tiff(TW, TH, 1, 8, lambda c, r: bytes([tile8(c, r)]), tiles=(16, 16)))
    write("grey16_tiles.tif", tiff(TW, TH, 1, 16, lambda c, r: struct.pack("<H", tile16(c, r)), tiles=(16, 16)))
    # compressed: Deflate (TIFF compression 8), one strip per row
    write("grey8_deflate.tif", tiff(TW, TH, 1, 8, lambda c, r: bytes([tile8(c, r)]), deflate=True))
    # a format the lab does not read: a 1 × 1 GIF
    write("unsupported.gif", b"GIF89a" + struct.pack("<HHBBB", 1, 1, 0x80, 0, 0) + b"\x00\x00\x00\xff\xff\xff"
          + b"\x2c" + struct.pack("<HHHHB", 0, 0, 1, 1, 0) + b"\x02\x02\x44\x01\x00" + b"\x3b")
    # bad files
    good = png(W, H, 8, 0, [bytes(grey8(c, r) for c in range(W)) for r in range(H)])
    write("truncated.png", good[: len(good) - 30])
    write("bad_crc.png", png(W, H, 8, 0, [bytes(grey8(c, r) for c in range(W)) for r in range(H)], bad_crc=True))
    write("zero_width.png", png(0, H, 8, 0, [b"" for _ in range(H)]))
    # a header that claims 100000 × 100000 (and a single tiny IDAT)
    ihdr = struct.pack(">IIBBBBB", 100000, 100000, 8, 0, 0, 0, 0)
    write("huge_header.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
          + chunk(b"IDAT", zlib.compress(b"\x00" * 1000)) + chunk(b"IEND", b""))
    # a decompression bomb: 5000 × 5000 zeros (25 MB of pixels) in a few kB
    side = 5000
    row = b"\x00" + b"\x00" * side
    comp = zlib.compressobj(9)
    idat = b"".join(comp.compress(row) for _ in range(side)) + comp.flush()
    ihdr = struct.pack(">IIBBBBB", side, side, 8, 0, 0, 0, 0)
    write("bomb.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b""))
    write("missing_tag.tif", tiff(W, H, 1, 8, lambda c, r: bytes([grey8(c, r)]), drop_tag=273))
    write("text.png", b"This is a text file, not a picture.\nIt was only renamed to .png.\n")
    write("empty.png", b"")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes the decode corpus of the lab's tests (standard library only).

Good files with known pixel values: grey 8-bit PNG, grey 16-bit PNG, RGB PNG,
TIFF 8-bit grey (strips), TIFF 16-bit grey (strips), TIFF 8-bit RGB (tiles),
TIFF 16-bit RGB (strips), TIFF 8-bit and 16-bit grey in several tiles,
TIFF 8-bit grey compressed with Deflate, a 24-bit BMP, a two-frame GIF (the
lab reads the first), a DNG whose first image is the full photo; and a QOI
header, a format the lab does not read. The JPEGs (also the eight with an
EXIF orientation) and the WebP are written by the lab's ignored test
`write_encoded` (flat 8×8 blocks, which baseline JPEG stores exactly).
Refused by their signature: a HEIC, an AVIF, a Canon CR3 (their `ftyp`
boxes), a Fujifilm RAF, an Olympus ORF, a Panasonic RW2, and TIFFs that are
RAW files (a Canon CR2, a Nikon NEF whose first image is a thumbnail, a DNG
whose first image is a preview).
Bad files: truncated PNG, PNG with a wrong CRC, zero-width PNG, a PNG header
claiming 100000×100000, a decompression bomb (7200×7200 zeros, 51.8
megapixels, in a few kB), a TIFF without its StripOffsets tag, a text file
named .png, an empty file.
The truncated JPEG is written by `write_encoded` too.

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


def tiff(width, height, spp, bps, pixel_bytes, tiles=None, drop_tag=None, deflate=False, extra=(), cr2=False):
    """Little-endian baseline TIFF, uncompressed (or each strip or tile
    zlib-compressed: `deflate`, compression 8); strips (one per row) or
    tiles (tile size `tiles`, padded). `extra`: more IFD0 entries
    (tag, type, count, value), a `bytes` value stored after the pixels
    (an ASCII Make); `cr2`: Canon's CR2 header (`CR`, version 2.0 and a RAW
    IFD offset after the TIFF header)."""
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
    # layout: header(8; 16 for CR2) | blobs | bits-per-sample array | offsets | counts | extra data | IFD
    offset = 16 if cr2 else 8
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
    extra_data = b""
    for t_, typ, count, value in extra:
        if isinstance(value, bytes):
            tag(t_, typ, count, offset + len(extra_data))
            extra_data += value
        else:
            tag(t_, typ, count, value)
    offset += len(extra_data)
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
    if cr2:
        head += b"CR\x02\x00" + struct.pack("<I", 0)
    return head + b"".join(data_blobs) + bps_arr + offs_arr + cnt_arr + extra_data + ifd


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
    # a format the lab does not read: a QOI header
    write("unsupported.qoi", b"qoif" + struct.pack(">IIBB", 4, 3, 3, 0) + b"\x00" * 7 + b"\x01")
    # BMP (24-bit, bottom-up rows padded to 4 bytes) and GIF (grey palette,
    # two frames: the lab reads the first) with the known pixels
    write("rgb8.bmp", bmp(W, H, rgb8))
    write("grey8.gif", gif(W, H, grey8))
    photos()
    # bad files
    good = png(W, H, 8, 0, [bytes(grey8(c, r) for c in range(W)) for r in range(H)])
    write("truncated.png", good[: len(good) - 30])
    write("bad_crc.png", png(W, H, 8, 0, [bytes(grey8(c, r) for c in range(W)) for r in range(H)], bad_crc=True))
    write("zero_width.png", png(0, H, 8, 0, [b"" for _ in range(H)]))
    # a header that claims 100000 × 100000 (and a single tiny IDAT)
    ihdr = struct.pack(">IIBBBBB", 100000, 100000, 8, 0, 0, 0, 0)
    write("huge_header.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
          + chunk(b"IDAT", zlib.compress(b"\x00" * 1000)) + chunk(b"IEND", b""))
    # a decompression bomb: 7200 × 7200 zeros (51.8 megapixels, over the
    # lab's 48; 1 bit a pixel) in a few kB
    side = 7200
    row = b"\x00" + b"\x00" * (side // 8)
    comp = zlib.compressobj(9)
    idat = b"".join(comp.compress(row) for _ in range(side)) + comp.flush()
    ihdr = struct.pack(">IIBBBBB", side, side, 1, 0, 0, 0, 0)
    write("bomb.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b""))
    write("missing_tag.tif", tiff(W, H, 1, 8, lambda c, r: bytes([grey8(c, r)]), drop_tag=273))
    write("text.png", b"This is a text file, not a picture.\nIt was only renamed to .png.\n")
    write("empty.png", b"")


def bmp(width, height, rgb):
    """A 24-bit BMP (BITMAPINFOHEADER, bottom-up, BGR, rows padded to 4 bytes)."""
    row_len = (3 * width + 3) // 4 * 4
    rows = b""
    for r in reversed(range(height)):
        row = b"".join(bytes(reversed(rgb(c, r))) for c in range(width))
        rows += row + b"\x00" * (row_len - len(row))
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(rows), 2835, 2835, 0, 0)
    return b"BM" + struct.pack("<IHHI", 14 + 40 + len(rows), 0, 0, 14 + 40) + info + rows


def gif(width, height, grey):
    """A GIF89a with a 256-entry grey palette (entry i is (i, i, i)) and two
    frames: `grey(c, r)`, then all 255. LZW with 9-bit codes: a clear code,
    one code per pixel, the end code (the table never reaches 512)."""
    def frame(values):
        bits, n = 0, 0
        for code in [256] + values + [257]:
            bits |= code << n
            n += 9
        data = bits.to_bytes((n + 7) // 8, "little")
        blocks = b"".join(bytes([len(data[i:i + 255])]) + data[i:i + 255] for i in range(0, len(data), 255))
        return (b"\x21\xf9\x04\x00\x00\x00\x00\x00"  # graphic control: no disposal, no delay
                + b"\x2c" + struct.pack("<HHHHB", 0, 0, width, height, 0) + b"\x08" + blocks + b"\x00")
    palette = b"".join(bytes([i, i, i]) for i in range(256))
    first = [grey(c, r) for r in range(height) for c in range(width)]
    return (b"GIF89a" + struct.pack("<HHBBB", width, height, 0xF7, 0, 0) + palette
            + frame(first) + frame([255] * (width * height)) + b"\x3b")


def iso(major, compatible):
    """The first box of an ISO base media file: `ftyp` with its brands."""
    body = major + b"\x00\x00\x00\x00" + b"".join(compatible)
    return struct.pack(">I", 8 + len(body)) + b"ftyp" + body


def photos():
    """Files the lab refuses by their signature (HEIC, AVIF, camera RAW),
    and TIFFs that are RAW files or a DNG that opens. Each TIFF here would
    decode as a 4 × 3 image: refused, it is not opened as its thumbnail."""
    write("iphone.heic", iso(b"heic", [b"mif1", b"heic"]) + struct.pack(">I", 8) + b"meta")
    write("photo.avif", iso(b"avif", [b"avif", b"mif1", b"miaf"]) + struct.pack(">I", 8) + b"meta")
    write("canon.cr3", iso(b"crx ", [b"crx ", b"isom"]) + struct.pack(">I", 8) + b"moov")
    write("fuji.raf", b"FUJIFILMCCD-RAW 0201FF129502" + b"\x00" * 36)
    write("olympus.orf", b"IIRO\x08\x00\x00\x00" + b"\x00" * 8)
    write("panasonic.rw2", b"IIU\x00\x08\x00\x00\x00" + b"\x00" * 8)
    px = lambda c, r: bytes(rgb8(c, r))
    write("canon.cr2", tiff(W, H, 3, 8, px, cr2=True))
    nikon = b"NIKON CORPORATION\x00"
    # IFD0 a thumbnail (NewSubfileType 1) with the sensor data in a SubIFD
    write("nikon.nef", tiff(W, H, 3, 8, px, extra=[(254, 4, 1, 1), (271, 2, len(nikon), nikon), (330, 4, 1, 8)]))
    dng = [(50706, 1, 4, 0x00000401)]  # DNGVersion 1.4.0.0 (4 bytes held in the entry)
    write("preview.dng", tiff(W, H, 3, 8, px, extra=[(254, 4, 1, 1)] + dng))
    write("full.dng", tiff(W, H, 3, 8, px, extra=[(254, 4, 1, 0)] + dng))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Regenerates the broken-input corpus (height/ and env/ here) and the small
valid fixtures in ../io/.  Run once after changing it; the outputs are checked in
and the tests never run this script.

Every format is written here from its specification with the standard
library only (struct, zlib), independently of hfshade_io's own writers and
of libpng / stb / OpenEXR, so the fixtures cross-check our loaders.  Each
broken file has exactly one defect, documented in README.md (the corpus test
fails if a file is missing there).
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
FIX = os.path.join(HERE, "..", "io")


def put(name, data, where=None):
    """Broken files go to env/ (Radiance, OpenEXR) or height/ (the rest)."""
    if where is None:
        env = name.startswith(("hdr_", "exr_")) or name.endswith((".hdr", ".exr"))
        where = os.path.join(HERE, "env" if env else "height")
    os.makedirs(where, exist_ok=True)
    with open(os.path.join(where, name), "wb") as f:
        f.write(data)


# ---- PNG ----------------------------------------------------------------------

def chunk(kind, data, crc=None):
    c = zlib.crc32(kind + data) & 0xFFFFFFFF if crc is None else crc
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", c)


def png(w, h, depth, ctype, rows, idat=None, iend=True, ihdr_crc=None, plte=None):
    sig = b"\x89PNG\r\n\x1a\n"
    ihdr = struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, 0)
    raw = b"".join(b"\x00" + r for r in rows)
    out = sig + chunk(b"IHDR", ihdr, ihdr_crc)
    if plte is not None:
        out += chunk(b"PLTE", plte)
    out += chunk(b"IDAT", zlib.compress(raw, 9) if idat is None else idat)
    if iend:
        out += chunk(b"IEND", b"")
    return out


def grey16_rows(w, h, f):
    return [b"".join(struct.pack(">H", f(i, j)) for i in range(w)) for j in range(h)]


# ---- OpenEXR (scanline, uncompressed unless told, one line per chunk) --------------

HALF, FLOAT, UINT = 1, 2, 0


def exr_attr(name, typ, data):
    return name + b"\0" + typ + b"\0" + struct.pack("<i", len(data)) + data


def exr(w, h, chans, pixel, comp=0, dw=None, version=2, xsamp=1, chunk_data=None,
        offsets=None):
    """chans: list of (name, type); pixel(name, i, j) -> value."""
    chans = sorted(chans)
    cl = b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", t, 0, xsamp, 1)
                  for n, t in chans) + b"\0"
    x0, y0, x1, y1 = dw if dw else (0, 0, w - 1, h - 1)
    box = struct.pack("<iiii", x0, y0, x1, y1)
    hdr = (exr_attr(b"channels", b"chlist", cl) +
           exr_attr(b"compression", b"compression", bytes([comp])) +
           exr_attr(b"dataWindow", b"box2i", box) +
           exr_attr(b"displayWindow", b"box2i", box) +
           exr_attr(b"lineOrder", b"lineOrder", b"\0") +
           exr_attr(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0)) +
           exr_attr(b"screenWindowCenter", b"v2f", struct.pack("<ff", 0, 0)) +
           exr_attr(b"screenWindowWidth", b"float", struct.pack("<f", 1.0)) + b"\0")
    head = b"\x76\x2f\x31\x01" + struct.pack("<i", version) + hdr
    chunks = []
    for j in range(h):
        if chunk_data is not None:
            data = chunk_data
        else:
            data = b""
            for n, t in chans:
                fmt = {HALF: "<e", FLOAT: "<f", UINT: "<I"}[t]
                for i in range(w):
                    data += struct.pack(fmt, pixel(n, i, j))
        chunks.append(struct.pack("<ii", y0 + j, len(data)) + data)
    pos = len(head) + 8 * h
    table = b""
    for k, c in enumerate(chunks):
        table += struct.pack("<Q", pos if offsets is None else offsets)
        pos += len(c)
    return head + table + b"".join(chunks)


def exr_value(n, i, j):
    return {"R": 1.0, "G": 2.0, "B": 4.0, "Y": 1.0}.get(n, 0.5) * (i + 1) + 0.25 * j


# ---- Radiance ------------------------------------------------------------------------

def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    import math
    f, e = math.frexp(m)
    s = f * 256.0 / m
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])


def hdr(w, h, pixel, head=None, rle=None):
    out = head if head is not None else (
        b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w))
    use_rle = (8 <= w < 32768) if rle is None else rle
    for j in range(h):
        px = [rgbe(*pixel(i, j)) for i in range(w)]
        if not use_rle:
            out += b"".join(px)
            continue
        out += bytes([2, 2, w >> 8, w & 255])
        for c in range(4):
            comp = bytes(p[c] for p in px)
            k = 0
            while k < w:  # literal dumps of up to 128 bytes
                n = min(128, w - k)
                out += bytes([n]) + comp[k:k + n]
                k += n
    return out


def hdr_value(i, j):
    # Exactly representable in RGBE: R is the largest, a power-of-two scale.
    return (float(4 + i), float(2 + j) * 0.5, 1.0)


def main():
    # ---------------- valid fixtures (../io) ----------------
    os.makedirs(FIX, exist_ok=True)
    put("grey16.png", png(3, 2, 16, 0, grey16_rows(3, 2, lambda i, j: 1000 * j + 300 * i + 1)), FIX)
    put("rgb_half.exr", exr(4, 3, [("R", HALF), ("G", HALF), ("B", HALF)], exr_value), FIX)
    put("y_float.exr", exr(3, 2, [("Y", FLOAT)], exr_value, dw=(10, -4, 12, -3)), FIX)
    put("flat.hdr", hdr(3, 2, hdr_value), FIX)
    put("rle.hdr", hdr(9, 2, hdr_value), FIX)

    # ---------------- empty, unknown, wrong magic ----------------
    put("empty.png", b"")
    put("empty_no_extension", b"")
    put("empty.hdr", b"")
    put("empty.exr", b"")
    put("text_nonsense.dat", b"this is not a height field\n")
    put("wrong_magic.png", b"GIF89a\x02\x00\x02\x00")
    put("wrong_magic.pgm", b"Q5 2 2 255\n\x01\x02\x03\x04")
    put("colour_ppm.ppm", b"P6 2 2 255\n" + bytes(12))
    os.makedirs(os.path.join(HERE, "height", "dir.png"), exist_ok=True)
    put(".gitkeep", b"", os.path.join(HERE, "height", "dir.png"))

    # ---------------- PNG ----------------
    good = png(4, 4, 16, 0, grey16_rows(4, 4, lambda i, j: i + 10 * j))
    put("png_truncated_signature.png", good[:5])
    put("png_truncated_ihdr.png", good[:20])
    idat_at = good.index(b"IDAT")
    put("png_truncated_idat.png", good[:idat_at + 4 + 10])
    put("png_no_iend.png", good[:-12])
    put("png_bad_ihdr_crc.png", png(4, 4, 16, 0, grey16_rows(4, 4, lambda i, j: 1), ihdr_crc=0x12345678))
    put("png_rgb.png", png(2, 2, 8, 2, [bytes(6), bytes(6)]))
    put("png_rgba16.png", png(2, 2, 16, 6, [bytes(16), bytes(16)]))
    put("png_palette.png", png(2, 2, 8, 3, [b"\0\0", b"\0\0"], plte=b"\xff\0\0"))
    put("png_zero_width.png", png(0, 4, 8, 0, [b""] * 4))
    put("png_huge.png", png(100000, 100000, 16, 0, [], idat=zlib.compress(b"\0" * 64)))
    put("png_1x1.png", png(1, 1, 8, 0, [b"\x05"]))
    put("png_corrupt_zlib.png", png(4, 4, 8, 0, [], idat=b"\x78\x9c\xde\xad\xbe\xef\x00\x11\x22\x33"))
    put("png_bad_depth.png", png(4, 4, 3, 0, [bytes(2)] * 4))
    put("png_missing_idat.png", good[:good.index(b"IDAT") - 4] + chunk(b"IEND", b""))
    put("png_all_transparent.png", png(2, 2, 8, 4, [b"\x10\x00\x20\x00", b"\x30\x00\x40\x00"]))

    # ---------------- PGM ----------------
    put("pgm_truncated_header.pgm", b"P5 4 4")
    put("pgm_zero_size.pgm", b"P5 0 0 255\n")
    put("pgm_negative_width.pgm", b"P5 -4 4 255\n" + bytes(16))
    put("pgm_overflow_size.pgm", b"P5 2147483648 2147483648 255\n" + bytes(16))
    put("pgm_absurd_digits.pgm", b"P5 99999999999999999999999 2 255\n" + bytes(16))
    put("pgm_over_guard.pgm", b"P5 20000 20000 255\n" + bytes(16))
    put("pgm_maxval_zero.pgm", b"P5 2 2 0\n" + bytes(4))
    put("pgm_maxval_65536.pgm", b"P5 2 2 65536\n" + bytes(8))
    put("pgm_short_data.pgm", b"P5 4 4 255\n" + bytes(10))
    put("pgm_short_data_16bit.pgm", b"P5 2 2 65535\n" + bytes(7))
    put("pgm_trailing_data.pgm", b"P5 2 2 255\n" + bytes(8))
    put("pgm_sample_over_maxval.pgm", b"P5 2 2 100\n\x01\x02\xc8\x04")
    put("pgm_garbage_header.pgm", b"P5 4x4 255\n" + bytes(16))
    put("pgm_no_separator.pgm", b"P5 2 2 255X\x01\x02\x03\x04")
    put("pgm_p2_garbage_sample.pgm", b"P2 2 2 255\n1 2\n3 abc\n")
    put("pgm_p2_short.pgm", b"P2 2 2 255\n1 2 3\n")
    put("pgm_p2_trailing.pgm", b"P2 2 2 255\n1 2 3 4 5\n")
    put("pgm_p2_negative_sample.pgm", b"P2 2 2 255\n1 2 3 -4\n")

    # ---------------- PFM ----------------
    def pfm(w, h, vals, scale=b"-1.0", magic=b"Pf"):
        return magic + b"\n%d %d\n" % (w, h) + scale + b"\n" + b"".join(struct.pack("<f", v) for v in vals)
    put("pfm_colour_PF.pfm", pfm(2, 2, [1.0] * 12, magic=b"PF"))
    put("pfm_short_data.pfm", pfm(2, 2, [1.0] * 3))
    put("pfm_trailing_data.pfm", pfm(2, 2, [1.0] * 5))
    put("pfm_scale_zero.pfm", pfm(2, 2, [1.0] * 4, scale=b"0.0"))
    put("pfm_scale_garbage.pfm", pfm(2, 2, [1.0] * 4, scale=b"abc"))
    put("pfm_scale_nan.pfm", pfm(2, 2, [1.0] * 4, scale=b"nan"))
    put("pfm_nan_only.pfm", pfm(2, 2, [float("nan")] * 4))
    put("pfm_nonfinite_only.pfm", pfm(2, 2, [float("nan"), float("inf"), float("-inf"), float("nan")]))
    put("pfm_overflow_size.pfm", b"Pf\n4294967296 4294967296\n-1.0\n" + bytes(16))
    put("pfm_1x1.pfm", pfm(1, 1, [1.0]))
    put("pfm_truncated_header.pfm", b"Pf\n2 2\n")
    put("pfm_missing_separator.pfm", b"Pf\n2 2\n-1.0" )

    # ---------------- ESRI ASCII grid ----------------
    hdr_ok = b"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
    put("asc_missing_ncols.asc", b"nrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 4\n")
    put("asc_missing_cellsize.asc", b"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\n1 2\n3 4\n")
    put("asc_garbage_number.asc", hdr_ok + b"1 2.5.1\n3 4\n")
    put("asc_nan_token.asc", hdr_ok + b"1 nan\n3 4\n")
    put("asc_hex_token.asc", hdr_ok + b"1 0x10\n3 4\n")
    put("asc_short_data.asc", hdr_ok + b"1 2\n3\n")
    put("asc_trailing_data.asc", hdr_ok + b"1 2\n3 4\n5\n")
    put("asc_negative_size.asc", b"ncols -2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 4\n")
    put("asc_overflow_size.asc", b"ncols 2147483648\nnrows 2147483648\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n")
    put("asc_fractional_size.asc", b"ncols 2.5\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 4\n")
    put("asc_all_nodata.asc", hdr_ok + b"NODATA_value -9999\n-9999 -9999\n-9999 -9999.0\n")
    put("asc_zero_cellsize.asc", b"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 0\n1 2\n3 4\n")
    put("asc_duplicate_key.asc", hdr_ok.replace(b"nrows 2\n", b"nrows 2\nnrows 2\n") + b"1 2\n3 4\n")
    put("asc_unknown_key.asc", hdr_ok + b"projection utm\n1 2\n3 4\n")
    put("asc_out_of_range.asc", hdr_ok + b"1 1e39\n3 4\n")
    put("asc_nonsquare_dxdy.asc", b"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ndx 1\ndy 2\n1 2\n3 4\n")
    put("asc_key_without_value.asc", b"ncols")
    put("asc_overlong_token.asc", hdr_ok + b"1 " + b"9" * 300 + b"\n3 4\n")

    # ---------------- raw float32 ----------------
    put("raw_short.4x4.raw", bytes(60))
    put("raw_long.4x4.raw", bytes(68))
    put("raw_without_size.raw", bytes(64))
    put("raw_nan_only.2x2.raw", struct.pack("<4f", *([float("nan")] * 4)))
    put("raw_too_small.1x4.raw", bytes(16))

    # ---------------- Radiance HDR ----------------
    put("hdr_wrong_magic.hdr", b"#?JUNK\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n" + bytes(16))
    put("hdr_truncated_header.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n")
    put("hdr_no_format.hdr", b"#?RADIANCE\nEXPOSURE=1\n\n-Y 2 +X 2\n" + bytes(16))
    put("hdr_xyze_format.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 2\n" + bytes(16))
    put("hdr_bad_orientation.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 2 +X 2\n" + bytes(16))
    put("hdr_garbage_size.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y abc +X 2\n" + bytes(16))
    put("hdr_zero_size.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 4\n")
    put("hdr_over_guard.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n" + bytes(16))
    put("hdr_overflow_size.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2147483648 +X 2147483648\n")
    put("hdr_claims_large.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n" + bytes(64))
    put("hdr_truncated_flat.hdr", hdr(3, 2, hdr_value)[:-5])
    put("hdr_truncated_rle.hdr", hdr(9, 2, hdr_value)[:-3])
    head = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n"
    put("hdr_bad_rle_run.hdr", head + bytes([2, 2, 0, 8]) + bytes([128 + 100, 7]) + bytes(40))
    put("hdr_bad_scanline_length.hdr", head + bytes([2, 2, 0, 9]) + bytes(40))

    # ---------------- OpenEXR ----------------
    rgb = [("R", HALF), ("G", HALF), ("B", HALF)]
    ok = exr(4, 3, rgb, exr_value)
    put("exr_wrong_magic.exr", b"\x76\x2f\x31\x02" + ok[4:])
    put("exr_bad_version.exr", ok[:4] + struct.pack("<i", 3) + ok[8:])
    put("exr_truncated_header.exr", ok[:40])
    put("exr_truncated_data.exr", ok[:-5])
    put("exr_bad_offsets.exr", exr(4, 3, rgb, exr_value, offsets=10 ** 9))
    put("exr_nan_pixel.exr", exr(4, 3, rgb, lambda n, i, j: float("nan") if (i, j) == (1, 1) else 1.0))
    put("exr_inf_pixel.exr", exr(2, 2, [("R", FLOAT), ("G", FLOAT), ("B", FLOAT)],
                                 lambda n, i, j: float("inf") if n == "B" else 1.0))
    put("exr_no_rgb.exr", exr(2, 2, [("Z", FLOAT)], exr_value))
    put("exr_partial_rgb.exr", exr(2, 2, [("R", HALF), ("G", HALF)], exr_value))
    put("exr_subsampled.exr", exr(2, 2, rgb, exr_value, xsamp=2))
    put("exr_huge_window.exr", exr(4, 3, rgb, exr_value, dw=(0, 0, 99999, 2)))
    put("exr_inverted_window.exr", exr(4, 3, rgb, exr_value, dw=(3, 0, 0, 2)))
    put("exr_corrupt_zips.exr", exr(4, 3, rgb, exr_value, comp=2,
                                    chunk_data=b"\x78\x9c\xde\xad\xbe\xef\x01\x02"))


if __name__ == "__main__":
    main()

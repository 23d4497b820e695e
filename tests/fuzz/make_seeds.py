#!/usr/bin/env python3
"""Regenerates the fuzz seed corpus (corpus/<target>/) and the dictionaries
(dict/<target>.dict).  Run once after changing it and check the outputs in;
neither the tests nor tools/fuzz.sh run it.  Deterministic: the same files
every time.

Seeds are small valid files of every variant each loader accepts (so the
fuzzer starts deep inside the decoders), plus a few files of the broken-input
corpus (tests/data/broken) and the valid fixtures (tests/data/io).  Formats
are written with the standard library only, reusing the writers of
tests/data/broken/make_corpus.py; the tiled and PIZ/PXR24/B44/DWA OpenEXR
seeds come from OpenEXR's own `exrmaketiled` (Debian package openexr) when
it is installed, and are kept as they are otherwise.
"""
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
BROKEN = os.path.join(ROOT, "tests", "data", "broken")
FIXTURES = os.path.join(ROOT, "tests", "data", "io")
sys.path.insert(0, BROKEN)
from make_corpus import (FLOAT, HALF, UINT, chunk, exr,  # noqa: E402
                         grey16_rows, hdr, hdr_value, png, rgbe)


def put(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def reuse(target, src_dir, *names):
    for n in names:
        with open(os.path.join(src_dir, n), "rb") as f:
            put(target, n, f.read())


# ---- PNG: every grey variant, filters, interlacing, ancillary chunks ------------

def pack_row(samples, depth, channels=1):
    if depth == 16:
        return b"".join(struct.pack(">H", s) for s in samples)
    if depth == 8:
        return bytes(samples)
    per = 8 // depth
    out = bytearray()
    for k in range(0, len(samples), per):
        b = 0
        for n, s in enumerate(samples[k:k + per]):
            b |= s << (8 - depth * (n + 1))
        out.append(b)
    return bytes(out)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def filter_rows(rows, bpp, kinds):
    """PNG filters 0..4 (one kind per row, cycling through kinds)."""
    out, prev = b"", bytes(len(rows[0]))
    for j, r in enumerate(rows):
        f = kinds[j % len(kinds)]
        enc = bytearray()
        for i, x in enumerate(r):
            a = r[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            pred = [0, a, b, (a + b) // 2, paeth(a, b, c)][f]
            enc.append((x - pred) & 255)
        out += bytes([f]) + bytes(enc)
        prev = r
    return out


def png_raw(w, h, depth, ctype, idat_data, extra=b"", interlace=0, split=0):
    sig = b"\x89PNG\r\n\x1a\n"
    out = sig + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, interlace))
    out += extra
    z = zlib.compress(idat_data, 9)
    if split:
        for k in range(0, len(z), split):
            out += chunk(b"IDAT", z[k:k + split])
    else:
        out += chunk(b"IDAT", z)
    return out + chunk(b"IEND", b"")


def adam7(w, h, value, depth):
    """Interlaced grey image data (filter 0), value(i, j) -> sample."""
    passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4),
              (1, 0, 2, 2), (0, 1, 1, 2)]
    data = b""
    for x0, y0, dx, dy in passes:
        xs = list(range(x0, w, dx))
        if not xs:
            continue
        for j in range(y0, h, dy):
            data += b"\0" + pack_row([value(i, j) for i in xs], depth)
    return data


def png_seeds():
    t = "height_png"
    v8 = lambda i, j: (37 * i + 11 * j) & 255  # noqa: E731
    put(t, "grey8_4x4.png", png(4, 4, 8, 0, [pack_row([v8(i, j) for i in range(4)], 8)
                                             for j in range(4)]))
    put(t, "grey16_5x3.png", png(5, 3, 16, 0, grey16_rows(5, 3, lambda i, j: 40000 + 999 * i - 7 * j)))
    for depth, w in ((1, 9), (2, 5), (4, 3)):
        m = (1 << depth) - 1
        rows = [pack_row([(i + j) & m for i in range(w)], depth) for j in range(3)]
        put(t, "grey%d_%dx3.png" % (depth, w), png(w, 3, depth, 0, rows))
    ga8 = [bytes(sum(([v8(i, j), 0 if (i, j) == (1, 1) else 255] for i in range(3)), []))
           for j in range(3)]
    put(t, "grey_alpha8_hole.png", png(3, 3, 8, 4, ga8))
    ga16 = [b"".join(struct.pack(">HH", 1000 * i + j, 0 if i == j else 65535) for i in range(3))
            for j in range(2)]
    put(t, "grey_alpha16_holes.png", png(3, 2, 16, 4, ga16))
    rows16 = [b"".join(struct.pack(">H", 300 * i + 5000 * j) for i in range(6)) for j in range(5)]
    put(t, "grey16_filters.png", png_raw(6, 5, 16, 0, filter_rows(rows16, 2, [0, 1, 2, 3, 4])))
    put(t, "grey8_interlaced_9x9.png", png_raw(9, 9, 8, 0, adam7(9, 9, v8, 8), interlace=1))
    put(t, "grey16_interlaced_5x3.png",
        png_raw(5, 3, 16, 0, adam7(5, 3, lambda i, j: 1000 * i + j, 16), interlace=1))
    extra = (chunk(b"gAMA", struct.pack(">I", 45455)) + chunk(b"sBIT", b"\x06") +
             chunk(b"tRNS", b"\x00\x07") + chunk(b"tEXt", b"Comment\0seed"))
    rows = b"".join(b"\0" + pack_row([v8(i, j) for i in range(4)], 8) for j in range(3))
    put(t, "grey8_ancillary_split_idat.png", png_raw(4, 3, 8, 0, rows, extra=extra, split=7))
    reuse(t, FIXTURES, "grey16.png")
    reuse(t, os.path.join(BROKEN, "height"), "png_truncated_idat.png", "png_bad_depth.png",
          "png_corrupt_zlib.png", "png_all_transparent.png", "png_palette.png")


# ---- PGM, PFM, ESRI grid, raw ---------------------------------------------------------

def pgm_seeds():
    t = "height_pgm"
    put(t, "p5_8bit_4x3.pgm", b"P5\n4 3\n255\n" + bytes((17 * k) & 255 for k in range(12)))
    put(t, "p5_16bit_3x3.pgm", b"P5 3 3 1000\n" + b"".join(struct.pack(">H", 111 * k) for k in range(9)))
    put(t, "p5_comments.pgm", b"P5\n# made by make_seeds.py\n2 # width\n2\n#maxval next\n7\n\x00\x07\x03\x05")
    put(t, "p2_3x2.pgm", b"P2\n3 2\n255\n0 128 255\n7 8 9\n")
    put(t, "p2_16bit_comments.pgm", b"P2 # ascii\n2 2 65535\n# data\n65535 0\n1 300\n")
    put(t, "p2_maxval1_crlf.pgm", b"P2\r\n3 2\r\n1\r\n0 1 0\r\n1 0 1\r\n")
    reuse(t, os.path.join(BROKEN, "height"), "pgm_short_data.pgm", "pgm_sample_over_maxval.pgm",
          "pgm_p2_trailing.pgm", "pgm_no_separator.pgm")


def pfm(w, h, vals, scale=b"-1.0", magic=b"Pf", little=True, sep=b"\n"):
    fmt = "<f" if little else ">f"
    return (magic + sep + b"%d %d" % (w, h) + sep + scale + b"\n" +
            b"".join(struct.pack(fmt, v) for v in vals))


def pfm_seeds():
    t = "height_pfm"
    nan, inf = float("nan"), float("inf")
    put(t, "pf_le_3x2.pfm", pfm(3, 2, [0.5 * k for k in range(6)]))
    put(t, "pf_be_2x3.pfm", pfm(2, 3, [100.0 - k for k in range(6)], scale=b"1.0", little=False))
    put(t, "pf_holes_4x4.pfm", pfm(4, 4, [nan if k in (5, 6) else (inf if k == 15 else float(k))
                                          for k in range(16)]))
    put(t, "pf_scale_exponent.pfm", pfm(2, 2, [1.0, 2.0, 3.0, 4.0], scale=b"-2.5e-1", sep=b" "))
    reuse(t, os.path.join(BROKEN, "height"), "pfm_colour_PF.pfm", "pfm_short_data.pfm",
          "pfm_scale_garbage.pfm")
    t = "pfm_image"
    put(t, "PF_le_2x2.pfm", pfm(2, 2, [0.25 * k for k in range(12)], magic=b"PF"))
    put(t, "PF_be_nonfinite.pfm", pfm(2, 1, [nan, inf, -inf, 1.0, -2.0, 3.0], magic=b"PF",
                                      scale=b"1", little=False))
    put(t, "Pf_1x1.pfm", pfm(1, 1, [42.0]))
    put(t, "Pf_3x1_be.pfm", pfm(3, 1, [1.0, nan, 3.0], scale=b"+4.0", little=False))
    reuse(t, os.path.join(BROKEN, "height"), "pfm_short_data.pfm", "pfm_trailing_data.pfm",
          "pfm_scale_nan.pfm")


def asc_seeds():
    t = "height_asc"
    put(t, "corner_3x2.asc", b"ncols 3\nnrows 2\nxllcorner 100.5\nyllcorner -20\ncellsize 30\n"
                             b"1 2 3\n4 5 6\n")
    put(t, "center_nodata_4x3.asc", b"NCOLS 4\nNROWS 3\nXLLCENTER 0\nYLLCENTER 0\nCELLSIZE 2.5\n"
                                    b"NODATA_value -9999\n1 -9999 3 4\n5 6 -9999.0 8\n9 10 11 12\n")
    put(t, "crlf_tabs.asc", b"ncols\t2\r\nnrows\t2\r\nxllcorner\t0\r\nyllcorner\t0\r\n"
                            b"cellsize\t1\r\n1.5\t-2.25\r\n+3e2\t4E-1\r\n")
    put(t, "float_max_nodata.asc", b"cellsize 1e-3\nncols 2\nnrows 3\nyllcorner 0\nxllcorner 0\n"
                                   b"nodata_value -3.4028235e+38\n"
                                   b"-3.4028235e+38 1\n2 3.4028234e38\n.5 7.\n")
    reuse(t, os.path.join(BROKEN, "height"), "asc_duplicate_key.asc", "asc_hex_token.asc",
          "asc_short_data.asc", "asc_nonsquare_dxdy.asc")


def raw_seeds():
    """Byte 0/1: size - 2 (mod 31), byte 2: bit 0 nodata 0.0, bit 1 no extension."""
    t = "height_raw"
    f32 = lambda vals: b"".join(struct.pack("<f", v) for v in vals)  # noqa: E731
    nan = float("nan")
    put(t, "2x2.bin", bytes([0, 0, 0]) + f32([1.0, 2.0, 3.0, 4.0]))
    put(t, "4x3_holes_nodata.bin", bytes([2, 1, 1]) +
        f32([0.0 if k in (1, 7) else (nan if k == 4 else float(k)) for k in range(12)]))
    put(t, "3x3_no_extension.bin", bytes([1, 1, 2]) + f32([float(k * k) for k in range(9)]))
    put(t, "8x5_sparse.bin", bytes([6, 3, 1]) + f32([float(k) if k % 9 == 0 else 0.0 for k in range(40)]))
    put(t, "pgm_content_no_extension.bin", bytes([0, 0, 2]) + b"P5 2 2 255\n\x01\x02\x03\x04")
    put(t, "short_2x2.bin", bytes([0, 0, 0]) + f32([1.0, 2.0, 3.0]))


# ---- Radiance HDR -----------------------------------------------------------------------

def rle(data, max_run, max_dump, run_code, dump_code):
    """Run-length coding: 3+ equal bytes as run_code(n) + byte (n <= max_run),
    other bytes as dump_code(n) + n bytes (n <= max_dump)."""
    out, k, n = b"", 0, len(data)
    while k < n:
        r = 1
        while k + r < n and r < max_run and data[k + r] == data[k]:
            r += 1
        if r >= 3:
            out += run_code(r) + bytes(data[k:k + 1])
            k += r
            continue
        s = k
        while k < n and k - s < max_dump:
            if k + 2 < n and data[k] == data[k + 1] == data[k + 2]:
                break
            k += 1
        out += dump_code(k - s) + bytes(data[s:k])
    return out


def rle_component(comp):
    """Radiance new-style RLE of one component: runs (128 + n, v), dumps (n, ...)."""
    return rle(comp, 127, 128, lambda n: bytes([128 + n]), lambda n: bytes([n]))


def hdr_runs(w, h, pixel, head=None):
    out = head or b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w)
    for j in range(h):
        px = [rgbe(*pixel(i, j)) for i in range(w)]
        out += bytes([2, 2, w >> 8, w & 255])
        for c in range(4):
            out += rle_component([p[c] for p in px])
    return out


def hdr_seeds():
    t = "env_hdr"
    reuse(t, FIXTURES, "flat.hdr", "rle.hdr")
    put(t, "rle_runs_40x3.hdr", hdr_runs(40, 3, lambda i, j: (1.0 if i < 20 else 8.0, 0.5, 0.25 * (j + 1))))
    put(t, "rgbe_exposure_flat_3x2.hdr",
        hdr(3, 2, hdr_value, head=b"#?RGBE\n# comment\nEXPOSURE=1.0\nFORMAT=32-bit_rle_rgbe\n"
                                  b"GAMMA=1\n\n-Y 2 +X 3\n"))
    put(t, "flat_width8_2x8.hdr", hdr(8, 2, hdr_value, rle=False))
    put(t, "black_rle_16x2.hdr", hdr_runs(16, 2, lambda i, j: (0.0, 0.0, 0.0)))
    reuse(t, os.path.join(BROKEN, "env"), "hdr_bad_rle_run.hdr", "hdr_truncated_rle.hdr",
          "hdr_bad_scanline_length.hdr", "hdr_claims_large.hdr")


# ---- OpenEXR ----------------------------------------------------------------------------

def exr_predict_reorder(raw):
    """ZIP/RLE pre-pass of OpenEXR: interleave split, then delta predictor."""
    t = raw[0::2] + raw[1::2]
    out = bytearray(t[:1])
    for k in range(1, len(t)):
        out.append((t[k] - t[k - 1] + 128 + 256) & 255)
    return bytes(out)


def exr_rle(data):
    """OpenEXR RLE: runs (n - 1, v), literals (-n, ...), signed counts."""
    return rle(data, 128, 127, lambda n: struct.pack("b", n - 1), lambda n: struct.pack("b", -n))


def exr_header(w, h, chans, comp):
    """The header of make_corpus.exr's scanline file (all before the offset
    table), with compression comp."""
    f = exr(w, h, chans, lambda n, i, j: 0, comp=comp)
    row = w * sum({HALF: 2, FLOAT: 4, UINT: 4}[t] for _, t in chans)
    return f[:len(f) - 8 * h - h * (8 + row)]


def exr_compressed(w, h, chans, pixel, comp):
    """Scanline EXR with compression comp: 0 none, 1 RLE, 2 ZIPS, 3 ZIP."""
    chans = sorted(chans)
    head = exr_header(w, h, chans, comp)
    lpc = 16 if comp == 3 else 1
    chunks = []
    for y in range(0, h, lpc):
        raw = b""
        for j in range(y, min(h, y + lpc)):
            for n, t in chans:
                fmt = {HALF: "<e", FLOAT: "<f", UINT: "<I"}[t]
                raw += b"".join(struct.pack(fmt, pixel(n, i, j)) for i in range(w))
        if comp == 1:
            data = exr_rle(exr_predict_reorder(raw))
        elif comp in (2, 3):
            data = zlib.compress(exr_predict_reorder(raw), 9)
        else:
            data = raw
        if len(data) >= len(raw):
            data = raw  # OpenEXR stores a chunk that does not shrink as is
        chunks.append(struct.pack("<ii", y, len(data)) + data)
    pos = len(head) + 8 * len(chunks)
    table = b""
    for c in chunks:
        table += struct.pack("<Q", pos)
        pos += len(c)
    return head + table + b"".join(chunks)


def exr_seeds():
    t = "env_exr"
    rgb = [("R", HALF), ("G", HALF), ("B", HALF)]
    smooth = lambda n, i, j: {"R": 1.0, "G": 0.5, "B": 0.25, "A": 1.0}[n] * (1 + (i // 8) + j // 4)  # noqa: E731
    reuse(t, FIXTURES, "rgb_half.exr", "y_float.exr")
    put(t, "rle_rgb_half_32x4.exr", exr_compressed(32, 4, rgb, smooth, 1))
    put(t, "zips_rgba_half_32x4.exr", exr_compressed(32, 4, rgb + [("A", HALF)], smooth, 2))
    put(t, "zip_rgb_float_32x20.exr", exr_compressed(32, 20, [(c, FLOAT) for c in "RGB"], smooth, 3))
    put(t, "uint_rgb_3x2.exr", exr(3, 2, [(c, UINT) for c in "RGB"], lambda n, i, j: i + 7 * j))
    reuse(t, os.path.join(BROKEN, "env"), "exr_bad_offsets.exr", "exr_truncated_data.exr",
          "exr_corrupt_zips.exr", "exr_subsampled.exr")
    tool = shutil.which("exrmaketiled")
    if not tool:
        print("exrmaketiled not found (package openexr): tiled EXR seeds kept as they are")
        return
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, "src.exr")
        with open(src, "wb") as f:
            f.write(exr(12, 10, rgb, smooth))
        runs = [("tiled_%s.exr" % z, ["-z", z, "-t", "8", "4"])
                for z in ("none", "rle", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab")]
        runs += [("tiled_mipmap_zip.exr", ["-m", "-z", "zip", "-t", "4", "4"]),
                 ("tiled_ripmap_none.exr", ["-r", "-u", "-z", "none", "-t", "8", "8"])]
        for name, args in runs:
            out = os.path.join(tmp, name)
            subprocess.run([tool] + args + [src, out], check=True, stdout=subprocess.DEVNULL)
            with open(out, "rb") as f:
                put(t, name, f.read())


# ---- scene files ----------------------------------------------------------------------

def scene_seeds():
    t = "scene"
    reuse(t, os.path.join(ROOT, "data"), "demo.ini")
    put(t, "every_key.ini", b"""# every single-valued key once
height = terrain.raw
size = 64x32
dx = 30.5
zscale = 2
nodata = -9999
env-map = /abs/sky.exr
env-rotate = -45
albedo = 0.75
k = 4
offset = 0
nphi-env = 32
nphi-key = 3
nphi-local = 16
subsample = 4
precision = fp32
backend = cpu
context = auto
visibility = wedge
threads = 2
truth-azimuths = 720
truth-samples = 64
local-swath = full
key = 135,35,4,3
key = 300,60,10,1
local = 10,20,5,1.5,100
""")
    sh = ",".join(["3.5449077"] + ["0"] * 15)
    put(t, "env_sh_locals.ini", ("; semicolon comment\nheight=a b/c.png ; inline comment\n"
                                 "env-sh = %s\n" % sh +
                                 "".join("local = %d,%d,1e1,0,%g\n" % (k, -k, 2.5 * k) for k in range(4)) +
                                 "key = -3600,-90,89,0\n").encode())
    put(t, "truth_settings.ini", b"height = h.asc\r\nbackend = truth\r\ntruth-azimuths = 100000\r\n"
                                 b"truth-samples = 1048576\r\nnphi-env = 1024\r\n")
    put(t, "bad_section.ini", b"height = x.png\n[lights]\nkey = 1,2,3,4\n")
    put(t, "bad_duplicate.ini", b"height = x.png\nheight = y.png\n")
    put(t, "bad_range.ini", b"height = x.png\nk = 0\n")
    put(t, "bad_both_env.ini", b"height = x.png\nenv-sh = " + sh.encode() + b"\nenv-map = e.hdr\n")
    put(t, "bad_no_height.ini", b"dx = 1\n")
    put(t, "bad_long_line.ini", b"height = " + b"d/" * 100 + b"x.png\n")
    put(t, "bad_size_wraps.ini", b"height = x.raw\nsize = 4294967298x2\n")  # sscanf took it as 2x2


# ---- dictionaries -------------------------------------------------------------------

def put_dict(target, entries):
    d = os.path.join(HERE, "dict")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, target + ".dict"), "w") as f:
        f.write("# libFuzzer dictionary for fuzz_%s (written by make_seeds.py)\n" % target)
        for k, e in enumerate(entries):
            esc = "".join(c if 32 <= ord(c) < 127 and c not in '"\\' else "\\x%02x" % ord(c)
                          for c in e)
            f.write('k%d="%s"\n' % (k, esc))


def dicts():
    with open(os.path.join(ROOT, "runtime", "scene", "scene.c")) as f:
        keys = re.findall(r'\[K_[A-Z_]+\] = \{"([a-z-]+)"', f.read())
    assert len(keys) >= 20, "scene key table not found"
    put_dict("scene", keys + [" = ", "=", "\n", "#", ";", "[", "]", ",", "x", "fp16", "fp32",
                              "gles", "cpu", "truth", "surfaceless", "osmesa", "auto", "legendre",
                              "wedge", "partial", "full", "1e9", "-1e9", "nan", "inf", "0x1p3",
                              "3.5449077", "65536", "2147483648"])
    put_dict("height_asc", ["ncols", "nrows", "xllcorner", "xllcenter", "yllcorner", "yllcenter",
                            "cellsize", "NODATA_value", "dx", "dy", "-9999", "-3.4028235e+38",
                            "3.4028236e38", "1e-45", "e+", "E-", ".", "-", "+", "\r\n", "\t"])
    put_dict("height_pgm", ["P5", "P2", "#", "\n", "255", "256", "65535", "65536", " 0 "])
    pfm_words = ["Pf", "PF", "-1.0", "1.0", "-1", "\n", " ", "\x00\x00\xc0\x7f", "\x7f\xc0\x00\x00",
                 "\x00\x00\x80\x7f", "16384"]
    put_dict("height_pfm", pfm_words)
    put_dict("pfm_image", pfm_words)
    put_dict("height_png", ["\x89PNG\r\n\x1a\n", "IHDR", "IDAT", "IEND", "PLTE", "tRNS", "gAMA",
                            "sBIT", "tEXt", "zTXt", "iCCP", "\x00\x00\x00\x0dIHDR", "\x78\x9c",
                            "\x78\xda", "\x10", "\x08\x00", "\x10\x04", "\x01\x00\x00"])
    put_dict("env_hdr", ["#?RADIANCE\n", "#?RGBE\n", "FORMAT=32-bit_rle_rgbe\n",
                         "FORMAT=32-bit_rle_xyze\n", "EXPOSURE=", "\n\n", "-Y ", " +X ", "+Y ",
                         "\x02\x02", "\x02\x02\x00\x08", "\x80", "\xff"])
    put_dict("env_exr", ["v/1\x01", "\x02\x00\x00\x00", "\x02\x02\x00\x00", "channels\x00chlist\x00",
                         "compression\x00compression\x00", "dataWindow\x00box2i\x00",
                         "displayWindow\x00box2i\x00", "lineOrder\x00lineOrder\x00",
                         "pixelAspectRatio\x00float\x00", "screenWindowCenter\x00v2f\x00",
                         "screenWindowWidth\x00float\x00", "tiles\x00tiledesc\x00",
                         "envmap\x00envmap\x00", "type\x00string\x00", "chunkCount\x00int\x00",
                         "R\x00", "G\x00", "B\x00", "Y\x00", "A\x00", "scanlineimage",
                         "tiledimage", "deepscanline", "\xff\xff\xff\x7f"])


def main():
    # Start afresh, except for the tiled EXR seeds when they cannot be remade.
    keep = "tiled_" if not shutil.which("exrmaketiled") else None
    for dirpath, _, files in os.walk(os.path.join(HERE, "corpus")):
        for f in files:
            if not (keep and f.startswith(keep)):
                os.remove(os.path.join(dirpath, f))
    png_seeds()
    pgm_seeds()
    pfm_seeds()
    asc_seeds()
    raw_seeds()
    hdr_seeds()
    exr_seeds()
    scene_seeds()
    dicts()
    total = 0
    for dirpath, _, files in os.walk(os.path.join(HERE, "corpus")):
        total += sum(os.path.getsize(os.path.join(dirpath, f)) for f in files)
    print("corpus: %d bytes" % total)


if __name__ == "__main__":
    main()

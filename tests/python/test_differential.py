"""A differential mutation fuzzer: damaged files judged by each format's own tools and by irid
(docs/RELIABILITY.md, "A second decoder").

Valid files of every codec and layout irid reads (TIFF strips, tiles, separate planes, predictor,
BigTIFF, LZW, PackBits, deflate; baseline, progressive, arithmetic and restart-interval JPEG;
PNG, interlaced too; scanline and tiled EXR of several compressions) are damaged, seeded and
bounded: a byte flipped, the file cut, a range duplicated or zeroed, the tail spliced from
another file of the format. Each is read by its format's reference and by irid.read_image; a
file the reference calls damaged and irid accepts is a failure, kept in the test's folder.

The references: libtiff's ``tiffinfo -D`` and ``tiffcp``; libjpeg's ``djpeg`` (an error, or a
warning about the coded data: the header-only warnings irid documents as harmless, such as
extraneous bytes before a marker, do not count); ``pngcheck``; OpenEXR's ``exrheader`` and a full
read through its library (tests/tools/exr_read_all).

IRID_DIFFERENTIAL_RUNS sets the damaged files per valid one (default 12 in the suite;
``IRID_DIFFERENTIAL_RUNS=300`` with several seeds before a submission), IRID_DIFFERENTIAL_SEED the
seed (1); with IRID_DIFFERENTIAL_SHOW_STRICTER set, the files irid alone refuses are printed
(with ``pytest -s``).
"""

import io
import os
import pathlib
import random
import shutil
import struct
import subprocess
import zlib

import numpy as np
import pytest

import irid

RUNS = int(os.environ.get("IRID_DIFFERENTIAL_RUNS", "12"))
SEED = int(os.environ.get("IRID_DIFFERENTIAL_SEED", "1"))
TOOLS = {name: shutil.which(name) for name in ("tiffinfo", "tiffcp", "djpeg", "cjpeg", "pngcheck",
                                               "exrheader", "oiiotool")}
EXR_READ_ALL = os.environ.get("IRID_EXR_READ_ALL")


def need_tools():
    missing = [n for n, p in TOOLS.items() if not p]
    assert not missing, f"missing {missing} (scripts/install-deps installs them)"
    if not EXR_READ_ALL:
        pytest.skip("IRID_EXR_READ_ALL is not set (run the suite through ctest)")


def pixels(h=40, w=48, channels=3, seed=7):
    rng = np.random.default_rng(seed)
    px = (rng.random((h, w, channels)) * 255).astype(np.uint8)
    px[:, : w // 2] = np.linspace(0, 255, w // 2, dtype=np.uint8)[None, :, None]   # smooth half
    return px


def adam7_png(px):
    """An interlaced (Adam7) 8-bit RGB PNG, every row unfiltered (ISO/IEC 15948 §8.2)."""
    h, w, _ = px.shape
    passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
    raw = b""
    for x0, y0, dx, dy in passes:
        sub = px[y0::dy, x0::dx]
        if sub.size:
            raw += b"".join(b"\0" + row.tobytes() for row in sub)

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 1)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def valid_files(folder):
    """(format, name, bytes) of every codec and layout."""
    from PIL import Image
    px = pixels()
    plain = folder / "plain.tif"
    Image.fromarray(px).save(plain)
    ppm = folder / "plain.ppm"
    Image.fromarray(px).save(ppm)
    files = []
    tiff_layouts = {
        "strips-deflate": ["-c", "zip", "-r", "8"], "predictor": ["-c", "zip:2", "-r", "8"],
        "bigtiff": ["-c", "zip", "-r", "8", "-8"], "tiles": ["-c", "zip", "-t", "-w", "16", "-l", "16"],
        "planar": ["-c", "zip", "-r", "8", "-p", "separate"], "lzw": ["-c", "lzw", "-r", "8"],
        "packbits": ["-c", "packbits", "-r", "8"], "none": ["-c", "none", "-r", "8"],
        "tiles-lzw": ["-c", "lzw", "-t", "-w", "16", "-l", "16"],
    }
    for name, args in tiff_layouts.items():
        out = folder / f"{name}.tif"
        subprocess.run([TOOLS["tiffcp"], *args, str(plain), str(out)], check=True)
        files.append(("tiff", name, out.read_bytes()))
    for name, args in {"baseline": [], "progressive": ["-progressive"], "arithmetic": ["-arithmetic"],
                       "restart": ["-restart", "1"], "optimized": ["-optimize"]}.items():
        out = subprocess.run([TOOLS["cjpeg"], "-quality", "90", *args, str(ppm)], check=True,
                             capture_output=True).stdout
        files.append(("jpeg", name, out))
    buf = io.BytesIO()
    Image.fromarray(px).save(buf, "PNG")
    files.append(("png", "plain", buf.getvalue()))
    files.append(("png", "interlaced", adam7_png(px)))
    base = folder / "base.exr"
    irid.write_image(base, px.astype(np.float32) / 255, compression="zip")
    for name, args in {"zip": ["--compression", "zip"], "piz": ["--compression", "piz"],
                       "rle": ["--compression", "rle"], "none": ["--compression", "none"],
                       "tiled": ["--tile", "16", "16", "--compression", "zip"]}.items():
        out = folder / f"{name}.exr"
        subprocess.run([TOOLS["oiiotool"], str(base), *args, "-o", str(out)], check=True)
        files.append(("exr", name, out.read_bytes()))
    return files


def mutate(data, rng, others):
    """One damage: a flipped byte, a cut, a duplicated or zeroed range, or a spliced tail; half
    of them within the file's first tenth, where the headers are."""
    data = bytearray(data)
    n = len(data)
    at = rng.randrange(8, max(9, n // 10)) if rng.random() < 0.5 else rng.randrange(8, n)
    kind = rng.choice(["flip", "cut", "duplicate", "zero", "splice"])
    if kind == "flip":
        data[at] ^= rng.randrange(1, 256)
    elif kind == "cut":
        del data[at:]
    elif kind == "duplicate":
        length = rng.randrange(1, min(64, n - at) + 1)
        data[at:at] = data[at:at + length]
    elif kind == "zero":
        length = rng.randrange(1, min(64, n - at) + 1)
        data[at:at + length] = bytes(length)
    else:
        other = rng.choice(others)
        data[at:] = other[rng.randrange(0, len(other)):]
    return bytes(data), f"{kind}@{at}"


HARMLESS_JPEG_WARNINGS = ("extraneous bytes before marker", "unknown JFIF revision number",
                          "Invalid SOS parameters for sequential JPEG",
                          "Unknown Adobe color transform code",
                          "thumbnail image size does not match data length")


def reference_refuses(fmt, path):
    """The reference's verdict and its reason."""
    def run(*cmd):
        return subprocess.run([str(c) for c in cmd], capture_output=True, text=True, errors="replace",
                              timeout=60)
    if fmt == "tiff":
        for cmd in ([TOOLS["tiffinfo"], "-D", path], [TOOLS["tiffcp"], "-c", "none", path, f"{path}.copy"]):
            r = run(*cmd)
            if r.returncode != 0:
                return True, r.stderr.strip()[:200]
        return False, ""
    if fmt == "jpeg":
        r = run(TOOLS["djpeg"], "-outfile", os.devnull, path)
        if r.returncode == 1:
            return True, r.stderr.strip()[:200]
        lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
        serious = [ln for ln in lines if not any(h in ln for h in HARMLESS_JPEG_WARNINGS)]
        return (bool(serious), "; ".join(serious)[:200])
    if fmt == "png":
        r = run(TOOLS["pngcheck"], "-q", path)
        return r.returncode != 0, (r.stdout + r.stderr).strip()[:200]
    for cmd in ([TOOLS["exrheader"], path], [EXR_READ_ALL, path]):
        r = run(*cmd)
        if r.returncode != 0:
            return True, (r.stdout + r.stderr).strip()[-200:]
    return False, ""


EXTENSION = {"tiff": "tif", "jpeg": "jpg", "png": "png", "exr": "exr"}


@pytest.mark.parametrize("fmt", ["tiff", "jpeg", "png", "exr"])
def test_irid_refuses_every_damaged_file_its_format_s_reference_refuses(tmp_path, fmt):
    need_tools()
    everything = valid_files(tmp_path)
    seeds = [(name, data) for f, name, data in everything if f == fmt]
    others = [data for _, data in seeds]
    rng = random.Random(f"{SEED}-{fmt}")
    failures, judged, both, stricter = [], 0, 0, 0
    for name, data in seeds:
        path = tmp_path / f"{name}.{EXTENSION[fmt]}"
        path.write_bytes(data)
        assert not reference_refuses(fmt, path)[0], f"{name}: the valid file is refused by its reference"
        irid.read_image(path)
        for k in range(RUNS):
            damaged, how = mutate(data, rng, others)
            path = tmp_path / f"{name}-{k}.{EXTENSION[fmt]}"
            path.write_bytes(damaged)
            refused, reason = reference_refuses(fmt, path)
            try:
                irid.read_image(path)
                accepted = True
            except OSError:
                accepted = False
            judged += 1
            if refused and accepted:
                failures.append(f"{path.name} ({how}): the reference says {reason!r}; irid reads it")
            elif refused:
                both += 1
                path.unlink()
            else:
                stricter += not accepted
                if not accepted and os.environ.get("IRID_DIFFERENTIAL_SHOW_STRICTER"):
                    try:
                        irid.read_image(path)
                    except OSError as e:
                        print(f"irid alone refuses {path.name} ({how}): {str(e)[-160:]}")
                path.unlink()
    print(f"{fmt}: {judged} damaged files, {both} refused by both, {stricter} refused by irid alone")
    assert not failures, "\n".join(failures)

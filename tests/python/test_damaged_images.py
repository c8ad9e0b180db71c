"""Every image is read whole or refused, and costs what it holds (docs/RELIABILITY.md).

- A file cut short, in every format irid reads (PNG, JPEG baseline and progressive, TIFF
  uncompressed, LZW and deflate, OpenEXR), is exit 1 from ``irid clip`` with the path and the
  reason, and OSError from ``irid.read_image``: never grey or black rows.
- A file of a few hundred bytes whose header declares a huge image is refused before decoding,
  in memory bounded by the program itself (OpenImageIO loaded), not by the declared size.
- A damaged embedded ICC profile (JPEG APP2 segments not numbered 1..N as ICC.1 Annex B.4
  says; a TIFF profile tag past the file) is refused as PNG's is, and ``--from`` overrides it
  with a note. Segments in another order than their numbers are joined by their numbers.
"""

import io
import os
import pathlib
import resource
import struct
import subprocess

import numpy as np
import pytest

import irid

COLORD = pathlib.Path("/usr/share/color/icc/colord")   # colord-data (scripts/install-deps)

# AddressSanitizer reserves terabytes of shadow memory as a program starts, which a data limit
# forbids: in the sanitizer build (whose ctest preset loads libasan) the runs go unlimited and
# only the refusal itself is checked; the Release build checks the memory too.
SANITIZED = "libasan" in os.environ.get("LD_PRELOAD", "")


def random_rgb(h=96, w=80, seed=3):
    return (np.random.default_rng(seed).random((h, w, 3)) * 255).astype(np.uint8)


def pil_bytes(pixels, fmt, **kw):
    from PIL import Image
    buf = io.BytesIO()
    Image.fromarray(pixels).save(buf, fmt, **kw)
    return buf.getvalue()


def run_limited(cli, *args, data_mb=None):
    """(exit status, stderr) of one irid run, its data segment (heap and private mappings)
    limited to `data_mb` megabytes when given."""
    def limit():
        size = data_mb << 20
        resource.setrlimit(resource.RLIMIT_DATA, (size, size))
    r = subprocess.run([cli, *map(str, args)], capture_output=True, text=True,
                       preexec_fn=limit if data_mb and not SANITIZED else None)
    return r.returncode, r.stderr


def whole_files():
    px = random_rgb()
    files = {
        "png": pil_bytes(px, "PNG"),
        "jpg": pil_bytes(px, "JPEG", quality=90),
        "progressive.jpg": pil_bytes(px, "JPEG", quality=90, progressive=True),
        "tif": pil_bytes(px, "TIFF"),
        "lzw.tif": pil_bytes(px, "TIFF", compression="tiff_lzw"),
        "deflate.tif": pil_bytes(px, "TIFF", compression="tiff_adobe_deflate"),
    }
    return files


@pytest.mark.parametrize("name", ["png", "jpg", "progressive.jpg", "tif", "lzw.tif", "deflate.tif",
                                  "exr"])
@pytest.mark.parametrize("keep", [0.5, 0.9])
def test_a_file_cut_short_is_refused(irid_cli, tmp_path, name, keep):
    if name == "exr":
        irid.write_image(tmp_path / "whole.exr", random_rgb().astype(np.float32) / 255,
                         compression="zip")
        data = (tmp_path / "whole.exr").read_bytes()
    else:
        data = whole_files()[name]
    whole = tmp_path / f"whole.{name}"
    whole.write_bytes(data)
    irid.read_image(whole)      # the uncut file reads
    cut = tmp_path / f"cut.{name}"
    cut.write_bytes(data[:int(len(data) * keep)])
    status, err = run_limited(irid_cli, "clip", "--method", "clamp", "--from", "srgb", cut,
                                  tmp_path / "out.png")
    assert status == 1, err
    assert str(cut) in err and ("truncated" in err or "damaged" in err or "corrupt" in err
                                or "cannot read" in err), err
    assert not (tmp_path / "out.png").exists()
    with pytest.raises(OSError, match="cut"):
        irid.read_image(cut)


def test_corrupt_jpeg_data_is_refused(tmp_path):
    """A marker inside the coded data (here a restart marker in a file without restart
    intervals). JPEG's coded data carry no checksum: damage that still decodes as Huffman codes
    cannot be told from an image, and is not claimed to be."""
    data = whole_files()["jpg"]
    sos = data.index(b"\xff\xda")
    data = data[:sos + 400] + b"\xff\xd3" + data[sos + 400:]
    (tmp_path / "bad.jpg").write_bytes(data)
    with pytest.raises(OSError, match="bad.jpg: cannot read the pixels"):
        irid.read_image(tmp_path / "bad.jpg")


def jpeg_declaring(width, height, progressive=False, stray=False):
    """A JPEG's headers with the frame's size patched, and 20 bytes of coded data; with `stray`
    a byte that is no marker ahead of the frame header (libjpeg skips it, with a warning)."""
    data = bytearray(pil_bytes(random_rgb(16, 16), "JPEG", quality=90, progressive=progressive))
    i = 2
    while True:
        marker, length = data[i + 1], struct.unpack(">H", data[i + 2:i + 4])[0]
        if marker in (0xC0, 0xC2):
            data[i + 5:i + 9] = struct.pack(">HH", height, width)
            if stray:
                data[i:i] = b"\x00"
                i += 1
        if marker == 0xDA:
            return bytes(data[:i + 2 + length + 20]) + b"\xff\xd9"
        i += 2 + length


def tiff_declaring(width, height, compression=1, strip_bytes=None, bits=32, sample_format=3,
                   counts_type=4, offsets_type=4):
    """A classic little-endian TIFF directory of 3 samples, one strip of `strip_bytes` at the
    end of a file of a few hundred bytes (none: as many as the pixels need uncompressed); the
    strip's offset and byte count of the given TIFF types (4 LONG, 9 SLONG, 8 SSHORT, 16 LONG8)."""
    need = width * height * 3 * bits // 8
    count = need if strip_bytes is None else strip_bytes
    entries = [(256, 4, 1, width), (257, 4, 1, height), (258, 3, 3, None), (259, 3, 1, compression),
               (262, 3, 1, 2), (273, offsets_type, 1, None), (277, 3, 1, 3), (278, 4, 1, height),
               (279, counts_type, 1, count), (284, 3, 1, 1), (339, 3, 3, None)]
    after = 8 + 2 + 12 * len(entries) + 4
    extra = struct.pack("<3H", bits, bits, bits) + struct.pack("<3H", *(3 * [sample_format]))
    long8_at = after + len(extra)
    extra += struct.pack("<Q", count)
    strip_at = after + len(extra)
    out = b""
    for tag, typ, n, value in entries:
        if tag == 258:
            out += struct.pack("<HHII", tag, typ, n, after)
        elif tag == 339:
            out += struct.pack("<HHII", tag, typ, n, after + 6)
        elif tag == 273:
            out += struct.pack("<HHII", tag, typ, n, strip_at)
        elif typ == 16:
            out += struct.pack("<HHII", tag, typ, n, long8_at)
        elif typ in (3, 8):
            out += struct.pack("<HHIHH", tag, typ, n, value, 0)
        else:
            out += struct.pack("<HHII", tag, typ, n, value)
    body = b"II*\0" + struct.pack("<I", 8) + struct.pack("<H", len(entries)) + out + b"\0\0\0\0"
    body += extra
    if strip_bytes is not None:
        body += bytes(strip_bytes)
    return body


def bigtiff_declaring(width, height, compression, strip_bytes):
    """The same as tiff_declaring in BigTIFF (8-byte offsets and counts, 20-byte entries)."""
    entries = [(256, 4, 1, width), (257, 4, 1, height), (258, 3, 1, 32), (259, 3, 1, compression),
               (262, 3, 1, 1), (273, 16, 1, None), (277, 3, 1, 1), (278, 4, 1, height),
               (279, 16, 1, strip_bytes), (339, 3, 1, 3)]
    strip_at = 16 + 8 + 20 * len(entries) + 8
    out = b""
    for tag, typ, n, value in entries:
        out += struct.pack("<HHQQ", tag, typ, n, strip_at if tag == 273 else value)
    return (b"II+\0" + struct.pack("<HHQ", 8, 0, 16) + struct.pack("<Q", len(entries)) + out +
            struct.pack("<Q", 0) + bytes(strip_bytes))


# A few hundred bytes that declare 8000 x 8000 or 8192 x 8192: refused from the header, within
# 384 MB of data, which a run needs to load OpenImageIO and read a small image (an 8000 x 8000
# float image alone is 768 MB; without the header checks these runs fail allocating it).
@pytest.mark.parametrize("name,data,reason", [
    ("huge.jpg", jpeg_declaring(8000, 8000), "need at least 187500 bytes of coded data"),
    ("huge-progressive.jpg", jpeg_declaring(8000, 8000, True), "bytes of coded data"),
    ("huge.tif", tiff_declaring(8192, 8192), "its strip 0 declares 805306368 bytes"),
    ("huge-deflate.tif", tiff_declaring(8192, 8192, 8, 200), "expand at most 1032-fold"),
    ("huge-lzw.tif", tiff_declaring(8192, 8192, 5, 200), "expand at most 3640-fold"),
    ("huge-packbits.tif", tiff_declaring(8192, 8192, 32773, 200), "expand at most 64-fold"),
    ("huge-raw.tif", tiff_declaring(8192, 8192, 1, 200), "bytes of uncompressed data cannot"),
    ("huge-slong.tif", tiff_declaring(8192, 8192, 8, 200, counts_type=9), "expand at most 1032"),
    ("huge-long8.tif", tiff_declaring(8192, 8192, 8, 200, counts_type=16), "expand at most 1032"),
    ("huge-sshort.tif", tiff_declaring(8192, 8192, 1, 200, counts_type=8), "uncompressed data"),
    ("huge-slong-offsets.tif", tiff_declaring(8192, 8192, 1, 200, offsets_type=9),
     "uncompressed data"),
    ("huge-big.tif", bigtiff_declaring(8192, 8192, 8, 200), "expand at most 1032"),
    ("huge-stray-byte.jpg", jpeg_declaring(8000, 8000, True, stray=True), "bytes of coded data"),
], ids=lambda v: v if isinstance(v, str) and v.startswith("huge") else "")
def test_a_small_file_declaring_a_huge_image_costs_what_it_holds(irid_cli, tmp_path, name, data,
                                                                 reason):
    assert len(data) < 1000
    (tmp_path / name).write_bytes(data)
    status, err = run_limited(irid_cli, "clip", "--method", "clamp", "--from", "srgb",
                              tmp_path / name, tmp_path / "out.exr", data_mb=384)
    assert status == 1 and reason in err, err
    with pytest.raises(OSError, match=reason):
        irid.read_image(tmp_path / name)


@pytest.mark.skipif(SANITIZED, reason="AddressSanitizer's shadow memory exceeds any data limit")
def test_a_small_image_reads_within_the_data_limit_of_the_test_above(irid_cli, tmp_path):
    (tmp_path / "small.jpg").write_bytes(whole_files()["jpg"])
    status, err = run_limited(irid_cli, "clip", "--method", "clamp", "--from", "srgb",
                              tmp_path / "small.jpg", tmp_path / "out.exr", data_mb=384)
    assert status == 0, err


def ycbcr_tiff(size):
    """An uncompressed TIFF of YCbCr subsampled 2 x 2 (TIFF 6.0 §21): 6 bytes per 2 x 2 block."""
    data = bytes([100, 110, 120, 130, 128, 128]) * ((size // 2) * (size // 2))
    entries = [(256, 3, 1, size), (257, 3, 1, size), (258, 3, 3, None), (259, 3, 1, 1),
               (262, 3, 1, 6), (273, 4, 1, None), (277, 3, 1, 3), (278, 3, 1, size),
               (279, 4, 1, len(data)), (284, 3, 1, 1), (530, 3, 2, None)]
    after = 8 + 2 + 12 * len(entries) + 4
    extra = struct.pack("<3H", 8, 8, 8)
    out = b""
    for tag, typ, n, value in entries:
        if tag == 258:
            out += struct.pack("<HHII", tag, typ, n, after)
        elif tag == 273:
            out += struct.pack("<HHII", tag, typ, n, after + len(extra))
        elif tag == 530:
            out += struct.pack("<HHIHH", tag, typ, n, 2, 2)
        elif typ == 3:
            out += struct.pack("<HHIHH", tag, typ, n, value, 0)
        else:
            out += struct.pack("<HHII", tag, typ, n, value)
    return b"II*\0" + struct.pack("<IH", 8, len(entries)) + out + b"\0\0\0\0" + extra + data


def jpeg_header_variants():
    """Whole JPEGs whose headers make libjpeg warn without losing a pixel."""
    plain = bytearray(pil_bytes(random_rgb(32, 40), "JPEG", quality=90))
    sos = plain.index(b"\xff\xda")
    length = struct.unpack(">H", plain[sos + 2:sos + 4])[0]
    odd_sos = bytearray(plain)
    odd_sos[sos + 2 + length - 2] = 0                 # Se = 0: "Invalid SOS parameters"
    jfif2 = bytearray(plain)
    jfif2[11] = 2                                     # JFIF 2.01: "unknown JFIF revision"
    app0_end = 4 + struct.unpack(">H", plain[4:6])[0]
    padded = plain[:app0_end] + b"\x00" + plain[app0_end:]   # "1 extraneous bytes before marker"
    return {"odd-sos.jpg": bytes(odd_sos), "jfif2.jpg": bytes(jfif2), "padded.jpg": bytes(padded)}


def test_valid_files_the_checks_must_not_refuse(tmp_path):
    (tmp_path / "ycbcr.tif").write_bytes(ycbcr_tiff(64))
    px, _ = irid.read_image(tmp_path / "ycbcr.tif")
    assert px.shape == (64, 64, 3)
    for name, data in jpeg_header_variants().items():
        (tmp_path / name).write_bytes(data)
        px, _ = irid.read_image(tmp_path / name)
        assert px.shape == (32, 40, 3), name


def test_the_bounds_pass_real_files_of_every_compression(tmp_path):
    """A flat image compresses best: the bounds must still let it through."""
    flat = np.zeros((512, 512, 3), np.uint8)
    for name, kw in [("flat.jpg", dict(quality=10)), ("flatp.jpg", dict(quality=10, progressive=True)),
                     ("flat-444.jpg", dict(quality=10, subsampling=0)),
                     ("flat.tif", {}), ("flat-lzw.tif", dict(compression="tiff_lzw")),
                     ("flat-deflate.tif", dict(compression="tiff_adobe_deflate")),
                     ("flat-packbits.tif", dict(compression="packbits"))]:
        fmt = "JPEG" if name.endswith(".jpg") else "TIFF"
        (tmp_path / name).write_bytes(pil_bytes(flat, fmt, **kw))
        px, _ = irid.read_image(tmp_path / name)
        assert px.shape == (512, 512, 3) and float(np.abs(px).max()) < 2 / 255, name


# --- embedded profiles damaged in their container --------------------------------------------

def prophoto():
    return (COLORD / "ProPhotoRGB.icc").read_bytes()


def jpeg_with_app2(pixels, chunks):
    """A JPEG with the given APP2 ICC_PROFILE segments, (sequence, count, data), after SOI."""
    plain = pil_bytes(pixels, "JPEG", quality=95)
    segments = b""
    for seq, count, data in chunks:
        body = b"ICC_PROFILE\0" + bytes([seq, count]) + data
        segments += b"\xff\xe2" + struct.pack(">H", len(body) + 2) + body
    return plain[:2] + segments + plain[2:]


def halves(profile):
    mid = len(profile) // 2
    return profile[:mid], profile[mid:]


@pytest.mark.parametrize("numbers", ids=str, argvalues=[
    [(1, 1), (1, 1)],          # duplicated
    [(2, 2), (2, 2)],          # the same number twice
    [(0, 1)],                  # numbered from 0
    [(1, 2)],                  # a segment missing
    [(1, 2), (2, 3)],          # counts differ
    [(1, 0)],                  # a count of 0
])
def test_misnumbered_jpeg_profile_segments_are_refused(irid_cli, tmp_path, numbers):
    px = random_rgb(8, 8)
    profile = prophoto()
    parts = [profile] if len(numbers) == 1 else list(halves(profile))
    if numbers == [(1, 1), (1, 1)]:
        parts = [profile, profile]
    path = tmp_path / "bad.jpg"
    path.write_bytes(jpeg_with_app2(px, [(s, n, d) for (s, n), d in zip(numbers, parts)]))
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", path, tmp_path / "out.png"],
                       capture_output=True, text=True)
    assert r.returncode == 1 and "bad.jpg: ICC profile: damaged" in r.stderr, r.stderr
    assert "Annex B.4" in r.stderr and "no ICC profile" not in r.stderr
    assert not (tmp_path / "out.png").exists()
    _, meta = irid.read_image(path)
    assert meta["icc_profile_rejected"] and meta["icc_profile"] is None
    assert "APP2" in meta["icc_profile_damage"]
    with pytest.raises(ValueError, match="damaged"):
        irid.image_space(meta)
    # --from overrides the damaged profile, and says so.
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--from", "adobe-rgb", path,
                        tmp_path / "out.png"], capture_output=True, text=True)
    assert r.returncode == 0 and "--from adobe-rgb overrides" in r.stderr, r.stderr


@pytest.mark.parametrize("tail", [b"", b"\x01"])
def test_an_icc_segment_too_short_for_its_header_is_a_damaged_profile(irid_cli, tmp_path, tail):
    """"ICC_PROFILE\\0" and no sequence number or count (12 or 13 bytes): a part of a profile,
    which libjpeg's readers skip, not the absence of one."""
    plain = pil_bytes(random_rgb(8, 8), "JPEG", quality=95)
    body = b"ICC_PROFILE\0" + tail
    path = tmp_path / "short.jpg"
    path.write_bytes(plain[:2] + b"\xff\xe2" + struct.pack(">H", len(body) + 2) + body + plain[2:])
    _, meta = irid.read_image(path)
    assert meta["icc_profile_rejected"]
    assert f"holds {len(body)} bytes, fewer than the 14 of its header" in meta["icc_profile_damage"]
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", path, tmp_path / "out.png"],
                       capture_output=True, text=True)
    assert r.returncode == 1 and "short.jpg: ICC profile: damaged" in r.stderr, r.stderr


def test_jpeg_profile_segments_are_joined_by_their_numbers(irid_cli, tmp_path):
    px = random_rgb(8, 8)
    first, second = halves(prophoto())
    ordered = tmp_path / "ordered.jpg"
    reversed_ = tmp_path / "reversed.jpg"
    ordered.write_bytes(jpeg_with_app2(px, [(1, 2, first), (2, 2, second)]))
    reversed_.write_bytes(jpeg_with_app2(px, [(2, 2, second), (1, 2, first)]))
    for path in (ordered, reversed_):
        _, meta = irid.read_image(path)
        assert meta["icc_profile"] == prophoto(), path
        assert irid.image_space(meta)["exact"] and "ProPhoto" in irid.image_space(meta)["origin"]
        run = subprocess.run([irid_cli, "clip", "--method", "clamp", path, tmp_path / "o.png"],
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stderr


def tiff_profile_entry(data):
    """The byte offset of the ICC profile entry (tag 34675) in a little-endian TIFF's first
    directory."""
    assert data[:4] == b"II*\0"
    ifd = struct.unpack("<I", data[4:8])[0]
    n = struct.unpack("<H", data[ifd:ifd + 2])[0]
    for i in range(n):
        at = ifd + 2 + 12 * i
        if struct.unpack("<H", data[at:at + 2])[0] == 34675:
            return at
    raise AssertionError("no ICC profile tag")


@pytest.mark.parametrize("field,value", [("count", 10_000_000), ("offset", 10_000_000),
                                         ("count", 0xFFFFFFF0)])
def test_a_tiff_profile_tag_past_the_file_is_refused(irid_cli, tmp_path, field, value):
    data = bytearray(pil_bytes(random_rgb(8, 8), "TIFF", icc_profile=prophoto()))
    at = tiff_profile_entry(data)
    data[at + (4 if field == "count" else 8):at + (8 if field == "count" else 12)] = \
        struct.pack("<I", value)
    path = tmp_path / "bad.tif"
    path.write_bytes(bytes(data))
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", path, tmp_path / "out.png"],
                       capture_output=True, text=True)
    assert r.returncode == 1, r.stderr
    assert "bad.tif: ICC profile: damaged: its ICC profile tag (34675) declares" in r.stderr
    _, meta = irid.read_image(path)
    assert meta["icc_profile_rejected"]
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--from", "adobe-rgb", path,
                        tmp_path / "out.png"], capture_output=True, text=True)
    assert r.returncode == 0 and "overrides" in r.stderr, r.stderr


# --- files whose space cannot be known --------------------------------------------------------

@pytest.mark.parametrize("fmt", ["JPEG", "TIFF"])
def test_cmyk_without_a_profile_is_refused_and_from_overrides_it(irid_cli, tmp_path, fmt):
    from PIL import Image
    path = tmp_path / ("cmyk.jpg" if fmt == "JPEG" else "cmyk.tif")
    Image.new("CMYK", (4, 4), (10, 200, 30, 40)).save(path, fmt)
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", path, tmp_path / "out.png"],
                       capture_output=True, text=True)
    assert r.returncode == 1 and "CMYK samples without an ICC profile" in r.stderr, r.stderr
    _, meta = irid.read_image(path)
    assert meta["cmyk"]
    with pytest.raises(ValueError, match="CMYK"):
        irid.image_space(meta)
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--from", "srgb", path,
                        tmp_path / "out.png"], capture_output=True, text=True)
    assert r.returncode == 0 and "--from srgb overrides" in r.stderr and "CMYK" in r.stderr, \
        r.stderr


@pytest.mark.parametrize("value,reason", [(1e30, "red x = 1e+30"), (-3.0, "red x = -3"),
                                          (float("nan"), "not finite")])
def test_exr_chromaticities_outside_any_real_encoding_are_refused(irid_cli, tmp_path, value,
                                                                  reason):
    irid.write_image(tmp_path / "a.exr", np.full((2, 2, 3), 0.5, np.float32),
                     color_space="rec2020-linear")
    data = (tmp_path / "a.exr").read_bytes()
    red_x = struct.pack("<f", 0.708)
    assert data.count(red_x) == 1
    (tmp_path / "b.exr").write_bytes(data.replace(red_x, struct.pack("<f", value)))
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", tmp_path / "b.exr",
                        tmp_path / "out.exr"], capture_output=True, text=True)
    assert r.returncode == 1 and "chromaticities" in r.stderr and reason in r.stderr, r.stderr


def test_notes_are_warnings_in_python(tmp_path):
    (tmp_path / "plain.png").write_bytes(pil_bytes(random_rgb(4, 4), "PNG"))
    px, meta = irid.read_image(tmp_path / "plain.png")
    with pytest.warns(UserWarning, match="no ICC profile; its values are taken as sRGB"):
        irid.clip_image(px, meta["channels"], "clamp", source=meta)
    # An integer file whose chromaticities say linear sRGB: its codes are taken as linear light.
    tagged = dict(meta, chromaticities=(0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329))
    with pytest.warns(UserWarning, match="source='srgb-linear' takes them as linear light"):
        irid.clip_image(px, meta["channels"], "clamp", source=tagged)

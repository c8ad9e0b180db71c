"""libtiff's own tools judge the TIFFs irid reads (docs/RELIABILITY.md, "A second decoder").

OpenImageIO 2.4 inflates a deflate TIFF's strips itself and fills a strip that fails with black
without a word, and libtiff decodes whatever bytes a strip offset points at. Here every damaged
file that libtiff's ``tiffinfo -D`` refuses is refused by irid too, with the strip and the reason,
and strips that share bytes with each other or with the file's header are refused before a
decoder runs.
"""

import os
import shutil
import struct
import subprocess
import zlib

import numpy as np
import pytest

import irid
from test_damaged_images import run_limited
from tiff_edit import Tiff

TIFFCP = shutil.which("tiffcp")      # libtiff-tools (scripts/install-deps)
TIFFINFO = shutil.which("tiffinfo")


def libtiff_refuses(path):
    """libtiff's verdict: ``tiffinfo -D`` decodes every strip of contiguous samples and exits 1
    on a decoding error; ``tiffcp`` (which decodes separate planes too, where ``tiffinfo -D``
    reads past a damaged strip) copies every sample and exits 1 on one."""
    info = subprocess.run([TIFFINFO, "-D", str(path)], capture_output=True, text=True)
    copy = subprocess.run([TIFFCP, "-c", "none", str(path), str(path) + ".copy.tif"],
                          capture_output=True, text=True)
    return info.returncode != 0 or copy.returncode != 0


def plain_tiff(tmp_path):
    from PIL import Image
    px = (np.random.default_rng(5).random((32, 40, 3)) * 255).astype(np.uint8)
    px[:, :20] = 128   # a part deflate compresses, a part it stores
    path = tmp_path / "plain.tif"
    Image.fromarray(px).save(path)
    return path


# tiffcp's options for each layout: strips of 4 rows, predictor 2, one strip, BigTIFF, tiles,
# separate planes.
LAYOUTS = {
    "strips": ["-c", "zip", "-r", "4"],
    "predictor": ["-c", "zip:2", "-r", "8"],
    "one-strip": ["-c", "zip", "-r", "32"],
    "bigtiff": ["-c", "zip", "-r", "4", "-8"],
    "tiles": ["-c", "zip", "-t", "-w", "16", "-l", "16"],
    "planar": ["-c", "zip", "-r", "4", "-p", "separate"],
}


def layout(tmp_path, name):
    assert TIFFCP and TIFFINFO, "libtiff-tools is missing (scripts/install-deps installs it)"
    out = tmp_path / f"{name}.tif"
    subprocess.run([TIFFCP, *LAYOUTS[name], str(plain_tiff(tmp_path)), str(out)], check=True)
    return out


@pytest.mark.parametrize("name", sorted(LAYOUTS))
@pytest.mark.parametrize("damage", ["cut", "flip", "zero"])
def test_damaged_deflate_data_are_judged_as_libtiff_judges(irid_cli, tmp_path, name, damage):
    whole = layout(tmp_path, name)
    assert not libtiff_refuses(whole)
    irid.read_image(whole)
    data = bytearray(whole.read_bytes())
    t = Tiff(data)
    offsets_tag, counts_tag = (324, 325) if 324 in t.entries else (273, 279)
    offsets, counts = t.values(offsets_tag), t.values(counts_tag)
    k = min(1, len(offsets) - 1)
    if damage == "cut":        # the unit's data cut in half, its byte count matching
        counts[k] //= 2
        t.set_values(counts_tag, counts)
    elif damage == "flip":     # one byte in the middle of its data
        data[offsets[k] + counts[k] // 2] ^= 0x55
    else:                      # its last 8 bytes (the end of the stream and its checksum) zeroed
        data[offsets[k] + counts[k] - 8:offsets[k] + counts[k]] = bytes(8)
    bad = tmp_path / f"bad-{name}.tif"
    bad.write_bytes(data)
    if not libtiff_refuses(bad):
        # The damage left a stream libtiff decodes whole (a flipped byte that still inflates and
        # whose checksum libtiff never reaches): irid reads it too.
        irid.read_image(bad)
        return
    unit = "tile" if offsets_tag == 324 else "strip"
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--from", "srgb", str(bad),
                        str(tmp_path / "out.png")], capture_output=True, text=True)
    assert r.returncode == 1, r.stderr
    assert f"its {unit} {k}'s deflate data" in r.stderr, r.stderr
    assert not (tmp_path / "out.png").exists()
    with pytest.raises(OSError, match=f"its {unit} {k}'s deflate data"):
        irid.read_image(bad)


def strips_tiff(width, height, rows_per_strip, streams, offsets_of=None):
    """A little-endian float TIFF of one sample: deflate strips of `rows_per_strip` rows, the
    data `streams` (one per strip, or one for all) placed after the directory; `offsets_of`
    maps the natural offsets to others (to make strips share bytes)."""
    strips = -(-height // rows_per_strip)
    if len(streams) == 1:
        streams = streams * strips
    entries = 11
    directory = 8 + 2 + 12 * entries + 4
    arrays = directory
    data_at = arrays + 8 * strips
    offsets, counts, body, seen = [], [], b"", {}
    for s in streams:
        if s not in seen:
            seen[s] = data_at + len(body)
            body += s
        offsets.append(seen[s])
        counts.append(len(s))
    if offsets_of is not None:
        offsets = offsets_of(offsets)
    fields = [(256, 4, 1, width), (257, 4, 1, height), (258, 3, 1, 32), (259, 3, 1, 8),
              (262, 3, 1, 1), (273, 4, strips, arrays if strips > 1 else offsets[0]),
              (277, 3, 1, 1), (278, 4, 1, rows_per_strip),
              (279, 4, strips, arrays + 4 * strips if strips > 1 else counts[0]),
              (284, 3, 1, 1), (339, 3, 1, 3)]
    out = b"II*\0" + struct.pack("<IH", 8, entries)
    for tag, typ, n, value in fields:
        out += struct.pack("<HHIHH", tag, typ, n, value, 0) if typ == 3 else struct.pack("<HHII", tag, typ, n, value)
    out += b"\0\0\0\0"
    if strips > 1:
        out += struct.pack(f"<{strips}I", *offsets) + struct.pack(f"<{strips}I", *counts)
    return out + body


def test_a_small_file_whose_strips_share_one_stream_is_refused_cheaply(irid_cli, tmp_path):
    """8192 x 8192 floats in 1024 strips, all pointing at one stream of a few hundred bytes: each
    strip decodes, and libtiff reads the file, 256 MB of zeros from 9 KB. irid refuses it from
    its directory, within the data limit of the huge-declaration tests."""
    stream = zlib.compress(bytes(8192 * 8 * 4), 9)
    data = strips_tiff(8192, 8192, 8, [stream])
    assert len(data) < 10000
    path = tmp_path / "shared.tif"
    path.write_bytes(data)
    status, err = run_limited(irid_cli, "clip", "--method", "clamp", "--from", "srgb-linear", path,
                              tmp_path / "out.exr", data_mb=384)
    assert status == 1 and "its strip 1 (bytes" in err and "overlaps its strip 0" in err, err
    with pytest.raises(OSError, match="overlaps its strip 0"):
        irid.read_image(path)


@pytest.mark.parametrize("where,what", [(0, "the file's header"), (8, "its directory"),
                                        (150, "its offsets array")])
def test_a_strip_on_the_header_directory_or_arrays_is_refused(tmp_path, where, what):
    streams = [zlib.compress(bytes([i]) * (64 * 4 * 4), 9) for i in range(4)]
    good = strips_tiff(64, 16, 4, streams)
    (tmp_path / "good.tif").write_bytes(good)
    assert irid.read_image(tmp_path / "good.tif")[0].shape == (16, 64, 1)
    bad = strips_tiff(64, 16, 4, streams, lambda o: [where] + o[1:])
    (tmp_path / "bad.tif").write_bytes(bad)
    with pytest.raises(OSError, match=f"its strip 0 \\(bytes {where} to .*\\) lies on {what}"):
        irid.read_image(tmp_path / "bad.tif")


# --- JPEG: what libjpeg's jpeg_finish_decompress stops at, which OpenImageIO never calls ------

DJPEG = shutil.which("djpeg")     # libjpeg-turbo-progs (scripts/install-deps)
CJPEG = shutil.which("cjpeg")


def djpeg_error(path):
    r = subprocess.run([DJPEG, "-outfile", "/dev/null", str(path)], capture_output=True, text=True)
    return r.returncode, r.stderr


def jpeg_of(seed, **kw):
    from PIL import Image
    import io
    buf = io.BytesIO()
    Image.fromarray((np.random.default_rng(seed).random((32, 48, 3)) * 255).astype(np.uint8)).save(
        buf, "JPEG", quality=90, **kw)
    return buf.getvalue()


def test_a_second_frame_after_the_scan_is_refused_as_libjpeg_refuses_it(tmp_path):
    """An image whose coded data run on into the headers of another image (the differential test
    found it by splicing): libjpeg decodes every row, then stops at the second SOF."""
    a, b = jpeg_of(1), jpeg_of(2)
    path = tmp_path / "two-frames.jpg"
    path.write_bytes(a[:-2] + b[2:])        # a without its EOI, then b without its SOI
    status, err = djpeg_error(path)
    assert status == 1 and "two SOF markers" in err, err
    with pytest.raises(OSError, match=r"a second frame header \(marker 0xC0\) at byte \d+, after the image's first scan"):
        irid.read_image(path)


def test_a_second_scan_of_a_single_scan_image_is_refused_and_progressive_scans_are_not(tmp_path):
    a = jpeg_of(3)
    sos = a.index(b"\xff\xda")
    length = struct.unpack(">H", a[sos + 2:sos + 4])[0]
    path = tmp_path / "two-scans.jpg"
    path.write_bytes(a[:-2] + a[sos:sos + 2 + length + 40] + b"\xff\xd9")
    status, err = djpeg_error(path)
    assert status == 1 and "Didn't expect more than one scan" in err, err
    with pytest.raises(OSError, match="a second scan at byte"):
        irid.read_image(path)
    (tmp_path / "progressive.jpg").write_bytes(jpeg_of(3, progressive=True))
    assert djpeg_error(tmp_path / "progressive.jpg")[0] == 0
    irid.read_image(tmp_path / "progressive.jpg")


def test_an_arithmetic_jpeg_can_hold_a_large_image_in_a_few_hundred_bytes(tmp_path):
    """Why arithmetic-coded JPEGs have no bound of coded bytes per block: the coder's smallest
    probability estimate (Qe = 0x0001, T.81 Table D.2) spends about 4e-5 bits on a likely
    decision, and a black 2048 x 2048 image takes under 300 bytes, headers included. irid reads
    it whole, as djpeg does; such files are bounded by the pixel limit alone."""
    from PIL import Image
    Image.new("RGB", (2048, 2048)).save(tmp_path / "black.ppm")
    data = subprocess.run([CJPEG, "-arithmetic", str(tmp_path / "black.ppm")], check=True,
                          capture_output=True).stdout
    assert len(data) < 300
    (tmp_path / "black.jpg").write_bytes(data)
    assert djpeg_error(tmp_path / "black.jpg")[0] == 0
    px, _ = irid.read_image(tmp_path / "black.jpg")
    assert px.shape == (2048, 2048, 3) and px.max() == 0.0


# --- TIFF: libtiff's own reading of the directories -------------------------------------------

def test_a_tag_value_libtiff_refuses_is_refused(tmp_path):
    data = bytearray(layout(tmp_path, "strips").read_bytes())
    t = Tiff(data)
    assert 274 in t.entries         # Orientation, 1 to 8 (TIFF 6.0)
    t.set_values(274, [41729])
    path = tmp_path / "orientation.tif"
    path.write_bytes(data)
    assert libtiff_refuses(path)
    with pytest.raises(OSError, match='libtiff: .*Bad value 41729 for "Orientation"'):
        irid.read_image(path)


def test_a_broken_chain_of_directories_is_refused(tmp_path):
    data = bytearray(layout(tmp_path, "strips").read_bytes())
    t = Tiff(data)
    next_at = t.ifd_end - 4
    offsets = t.values(273)
    data[next_at:next_at + 4] = struct.pack("<I", offsets[1] + 1)   # a "directory" in strip 1
    path = tmp_path / "chain.tif"
    path.write_bytes(data)
    assert libtiff_refuses(path)
    with pytest.raises(OSError, match="libtiff: "):
        irid.read_image(path)


# --- EXR: the chunk table ---------------------------------------------------------------------

EXR_READ_ALL = os.environ.get("IRID_EXR_READ_ALL")


@pytest.mark.parametrize("compression,damage", [("none", "offset"), ("zip", "offset"),
                                                 ("rle", "line"), ("piz", "size")])
def test_a_broken_chunk_table_is_refused_as_openexr_reads_it_incomplete(tmp_path, compression, damage):
    if not EXR_READ_ALL:
        pytest.skip("IRID_EXR_READ_ALL is not set (run the suite through ctest)")
    path = tmp_path / "whole.exr"
    irid.write_image(path, np.random.default_rng(4).random((40, 24, 3)).astype(np.float32),
                     compression=compression)
    data = bytearray(path.read_bytes())
    end = header_end(data)       # the chunk table follows the header
    first = struct.unpack("<Q", data[end:end + 8])[0]
    assert first > end
    if damage == "offset":
        data[end + 8:end + 16] = bytes(8)                  # chunk 1 at byte 0
        reason = "its chunk 1 lies at byte 0"
    elif damage == "line":
        second = struct.unpack("<Q", data[end + 8:end + 16])[0]
        data[second:second + 4] = struct.pack("<i", 7)    # chunk 1 claims line 7
        reason = "its chunk 1 at byte .* holds line 7 where line 1 belongs"
    else:
        data[first + 4:first + 8] = struct.pack("<I", 10**9)
        reason = "its chunk 0 at byte .* declares 1000000000 bytes"
    (tmp_path / "bad.exr").write_bytes(data)
    r = subprocess.run([EXR_READ_ALL, str(tmp_path / "bad.exr")], capture_output=True, text=True)
    assert r.returncode != 0, r.stderr
    with pytest.raises(OSError, match=reason):
        irid.read_image(tmp_path / "bad.exr")


def header_end(data):
    """The byte after an EXR single-part header's terminating zero (attributes: name, type, size,
    value)."""
    pos = 8
    while data[pos] != 0:
        name_end = data.index(b"\0", pos)
        type_end = data.index(b"\0", name_end + 1)
        size = struct.unpack("<I", data[type_end + 1:type_end + 5])[0]
        pos = type_end + 5 + size
    return pos + 1


@pytest.mark.parametrize("arithmetic", [False, True])
def test_a_jpeg_without_its_eoi_or_with_a_marker_libjpeg_does_not_know_is_refused(tmp_path, arithmetic):
    """The seeded differential run found both in arithmetic-coded files, whose last rows can be
    read before the decoder looks for the end (so OpenImageIO's row reads never see it)."""
    from PIL import Image
    Image.fromarray((np.random.default_rng(6).random((32, 48, 3)) * 255).astype(np.uint8)).save(tmp_path / "a.ppm")
    data = subprocess.run([CJPEG, *(["-arithmetic"] if arithmetic else []), str(tmp_path / "a.ppm")],
                          check=True, capture_output=True).stdout
    cases = {"no-eoi": (data[:-2], "without its EOI marker"),
             "unknown-marker": (data[:-2] + b"\xff\x25\x00\x04ab" + b"\xff\xd9", r"0x25\) at byte")}
    for name, (damaged, reason) in cases.items():
        path = tmp_path / f"{name}.jpg"
        path.write_bytes(damaged)
        status, err = djpeg_error(path)
        assert status != 0, (name, err)
        with pytest.raises(OSError, match=reason):
            irid.read_image(path)


@pytest.mark.parametrize("predictor", [3, 7])
def test_a_predictor_libtiff_cannot_apply_is_refused(tmp_path, predictor):
    """libtiff sets a strip's predictor up before decoding it, and refuses floating-point
    prediction of 8-bit integers (or a predictor it does not know); OpenImageIO read such files
    (found by the seeded differential run, seed 3)."""
    data = bytearray(layout(tmp_path, "predictor").read_bytes())
    t = Tiff(data)
    assert t.values(317) == [2]
    t.set_values(317, [predictor])
    path = tmp_path / "predictor.tif"
    path.write_bytes(data)
    assert libtiff_refuses(path)
    with pytest.raises(OSError, match=f"its predictor {predictor} cannot apply to 8-bit samples"):
        irid.read_image(path)

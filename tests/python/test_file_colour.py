"""What a file says about its colour is honoured or refused, never guessed (docs/RELIABILITY.md,
"What a file says about its colour").

- YCCK (a JPEG's Adobe transform 2) and CIELab TIFFs (photometric 8) reach irid as
  OpenImageIO's RGB made without a profile: refused as CMYK is, and ``--from`` overrides them
  with a note. (OpenImageIO refuses ICCLab, photometric 9, itself.)
- A TIFF's ICC profile tag is read whatever its integer type (libtiff keeps only UNDEFINED and
  BYTE); two tags holding different profiles are a damaged profile.
"""

import io
import pathlib
import shutil
import struct
import subprocess
import zlib

import numpy as np
import pytest

import irid
from tiff_edit import Tiff, with_entry

COLORD = pathlib.Path("/usr/share/color/icc/colord")   # colord-data (scripts/install-deps)


def pixels(seed=1, channels=3, size=8):
    return (np.random.default_rng(seed).random((size, size, channels)) * 255).astype(np.uint8)


def save(array, fmt, mode=None, **kw):
    from PIL import Image
    buf = io.BytesIO()
    Image.fromarray(array, mode).save(buf, fmt, **kw)
    return bytearray(buf.getvalue())


def ycck_jpeg():
    """A CMYK JPEG with its Adobe APP14 transform set to 2: the same coded components read as
    YCCK, which libjpeg converts to CMYK and OpenImageIO names "YCbCrK"."""
    data = save(pixels(channels=4), "JPEG", "CMYK", quality=95)
    at = data.index(b"\xff\xeeAdobe") if b"\xff\xeeAdobe" in data else data.index(b"\xff\xee")
    assert data[at + 4:at + 9] == b"Adobe"
    assert data[at + 15] == 0   # marker, length (2), "Adobe", version (2), flags (2 + 2), transform
    data[at + 15] = 2
    return data


def lab_tiff(photometric):
    data = save(pixels(), "TIFF", "LAB")
    t = Tiff(data)
    assert t.values(262) == [8]
    t.set_values(262, [photometric])
    return data


@pytest.mark.parametrize("name,data,model", [
    ("ycck.jpg", ycck_jpeg(), "YCCK"),
    ("cielab.tif", lab_tiff(8), "CIELab"),
])
def test_samples_converted_without_a_profile_are_refused(irid_cli, tmp_path, name, data, model):
    path = tmp_path / name
    path.write_bytes(data)
    _, meta = irid.read_image(path)
    assert meta["model"] == model
    assert meta["cmyk"] == (model == "YCCK")
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", str(path), str(tmp_path / "out.png")],
                       capture_output=True, text=True)
    assert r.returncode == 1 and f"holds {model} samples" in r.stderr, r.stderr
    assert not (tmp_path / "out.png").exists()
    with pytest.raises(ValueError, match=f"holds {model} samples"):
        irid.image_space(meta)
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--from", "srgb", str(path),
                        str(tmp_path / "out.png")], capture_output=True, text=True)
    assert r.returncode == 0 and f"--from srgb overrides what {path} says" in r.stderr, r.stderr


def test_icc_lab_tiffs_are_refused_by_the_decoder(tmp_path):
    (tmp_path / "icclab.tif").write_bytes(lab_tiff(9))
    with pytest.raises(OSError, match="PhotometricInterpretation=9"):
        irid.read_image(tmp_path / "icclab.tif")


def test_plain_rgb_files_name_no_model(tmp_path):
    for name, data in [("a.jpg", save(pixels(), "JPEG")), ("a.tif", save(pixels(), "TIFF")),
                       ("a.png", save(pixels(), "PNG"))]:
        (tmp_path / name).write_bytes(data)
        _, meta = irid.read_image(tmp_path / name)
        assert meta["model"] is None and meta["cmyk"] is False, name


def tagged_tiff():
    return save(pixels(), "TIFF", icc_profile=(COLORD / "AdobeRGB1998.icc").read_bytes())


@pytest.mark.parametrize("type_,size", [(1, 1), (4, 4), (3, 2), (9, 4)])
def test_a_tiff_profile_of_any_integer_type_is_read(irid_cli, tmp_path, type_, size):
    """libtiff keeps tag 34675 only when typed UNDEFINED (7) or BYTE (1), and OpenImageIO then says
    the file has no profile: irid reads the same bytes whatever their integer type."""
    whole = tagged_tiff()
    (tmp_path / "undefined.tif").write_bytes(whole)
    data = bytearray(whole)
    t = Tiff(data)
    e = t.entries[34675]
    assert e.type == 7 and e.count % size == 0
    data[e.entry_at + 2:e.entry_at + 8] = struct.pack("<HI", type_, e.count // size)
    (tmp_path / "typed.tif").write_bytes(data)
    _, meta = irid.read_image(tmp_path / "typed.tif")
    assert meta["icc_profile"] == (COLORD / "AdobeRGB1998.icc").read_bytes()
    assert irid.image_space(meta)["space"] == "adobe-rgb"
    for name in ("undefined", "typed"):
        r = subprocess.run([irid_cli, "clip", "--method", "clamp", str(tmp_path / f"{name}.tif"),
                            str(tmp_path / f"{name}.exr")], capture_output=True, text=True)
        assert r.returncode == 0 and "no ICC profile" not in r.stderr, r.stderr
    a, _ = irid.read_image(tmp_path / "undefined.exr")
    b, _ = irid.read_image(tmp_path / "typed.exr")
    assert np.array_equal(a, b)


def test_a_tiff_profile_typed_as_text_is_damage(tmp_path):
    data = tagged_tiff()
    Tiff(data).set_type(34675, 2)   # ASCII
    (tmp_path / "ascii.tif").write_bytes(data)
    _, meta = irid.read_image(tmp_path / "ascii.tif")
    assert meta["icc_profile_rejected"] and "of TIFF type 2" in meta["icc_profile_damage"]


def test_two_different_tiff_profiles_are_damage_and_equal_ones_are_one(irid_cli, tmp_path):
    whole = tagged_tiff()
    srgb = (COLORD / "sRGB.icc").read_bytes()
    (tmp_path / "two.tif").write_bytes(with_entry(bytes(whole), 34675, 7, len(srgb), srgb))
    _, meta = irid.read_image(tmp_path / "two.tif")
    assert meta["icc_profile_rejected"] and "two ICC profile tags" in meta["icc_profile_damage"]
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", str(tmp_path / "two.tif"),
                        str(tmp_path / "out.png")], capture_output=True, text=True)
    assert r.returncode == 1 and "two ICC profile tags (34675) with different profiles" in r.stderr
    adobe = (COLORD / "AdobeRGB1998.icc").read_bytes()
    (tmp_path / "same.tif").write_bytes(with_entry(bytes(whole), 34675, 7, len(adobe), adobe))
    _, meta = irid.read_image(tmp_path / "same.tif")
    assert not meta["icc_profile_rejected"] and meta["icc_profile"] == adobe


# --- PNG: cICP, then iCCP, then sRGB, then gAMA with cHRM (ISO/IEC 15948 §11.3.3; PNG Third
# Edition §11.3.2.6 puts cICP first) -----------------------------------------------------------

PNGCHECK = shutil.which("pngcheck")   # pngcheck (scripts/install-deps)


def chunk(type_, data):
    body = type_ + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


def png_with(chunks, after_data=(), value=128, **kw):
    """An 8-bit RGB PNG of 4 x 4 samples `value`, with `chunks` (type, data) after IHDR and
    `after_data` after the image data."""
    data = bytes(save(np.full((4, 4, 3), value, np.uint8), "PNG", **kw))
    ihdr_end = 8 + 8 + 13 + 4
    iend = data.rindex(b"IEND") - 4
    return (data[:ihdr_end] + b"".join(chunk(t, d) for t, d in chunks) + data[ihdr_end:iend] +
            b"".join(chunk(t, d) for t, d in after_data) + data[iend:])


def gama(g):
    return (b"gAMA", struct.pack(">I", round(g * 100000)))


REC2020_CHRM = (b"cHRM", struct.pack(">8I", 31270, 32900, 70800, 29200, 17000, 79700, 13100, 4600))


def pngcheck_refuses(path):
    assert PNGCHECK, "pngcheck is missing (scripts/install-deps installs it)"
    return subprocess.run([PNGCHECK, str(path)], capture_output=True).returncode != 0


def clip_to_exr(irid_cli, path, out, *args):
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--to", "srgb-linear", *args, str(path),
                        str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return irid.read_image(out)[0], r.stderr


def test_a_linear_rec2020_png_is_read_as_its_chunks_say(irid_cli, tmp_path):
    """gAMA 1.0 with cHRM of Rec.2020 and no iCCP: linear Rec.2020, exactly as --from says it."""
    path = tmp_path / "linear2020.png"
    path.write_bytes(png_with([gama(1.0), REC2020_CHRM]))
    assert not pngcheck_refuses(path)
    _, meta = irid.read_image(path)
    assert meta["png"]["gamma"] == 1.0 and len(meta["png"]["chromaticities"]) == 8
    facts = irid.image_space(meta)
    assert facts["space"] == "rec2020-linear" and not facts["assumed"], facts
    own, err = clip_to_exr(irid_cli, path, tmp_path / "own.exr")
    assert "no ICC profile" not in err and "takes them as linear light" not in err, err
    given, _ = clip_to_exr(irid_cli, path, tmp_path / "given.exr", "--from", "rec2020-linear")
    assert np.array_equal(own, given)
    assumed, _ = clip_to_exr(irid_cli, path, tmp_path / "srgb.exr", "--from", "srgb")
    assert abs(own[0, 0, 1] - 128 / 255) < 1e-6 and abs(assumed[0, 0, 1] - 0.2158605) < 1e-5


def test_a_gamma_without_chromaticities_decodes_with_its_power_law(irid_cli, tmp_path):
    path = tmp_path / "g45.png"
    path.write_bytes(png_with([gama(0.45455)]))
    _, meta = irid.read_image(path)
    facts = irid.image_space(meta)
    assert "gAMA 0.45455" in facts["origin"] and "sRGB's primaries" in facts["origin"]
    own, _ = clip_to_exr(irid_cli, path, tmp_path / "own.exr")
    assert np.allclose(own, (128 / 255) ** (1 / 0.45455), rtol=1e-5)


def test_an_srgb_chunk_says_srgb_and_an_icc_profile_comes_first(irid_cli, tmp_path):
    path = tmp_path / "srgb.png"
    path.write_bytes(png_with([(b"sRGB", b"\0"), gama(1.0)]))
    facts = irid.image_space(irid.read_image(path)[1])
    assert facts["space"] == "srgb" and not facts["assumed"] and facts["origin"] == "its sRGB chunk"
    _, err = clip_to_exr(irid_cli, path, tmp_path / "out.exr")
    assert "no ICC profile" not in err, err
    adobe = (COLORD / "AdobeRGB1998.icc").read_bytes()
    path.write_bytes(png_with([gama(1.0), REC2020_CHRM], icc_profile=adobe))
    assert irid.image_space(irid.read_image(path)[1])["space"] == "adobe-rgb"


@pytest.mark.parametrize("codes,space", [((1, 13, 0, 1), "srgb"), ((12, 13, 0, 1), "display-p3"),
                                         ((9, 8, 0, 1), "rec2020-linear")])
def test_cicp_comes_before_every_other_colour_chunk(tmp_path, codes, space):
    path = tmp_path / "cicp.png"
    path.write_bytes(png_with([(b"cICP", bytes(codes)), gama(1.0), REC2020_CHRM],
                              icc_profile=(COLORD / "AdobeRGB1998.icc").read_bytes()))
    assert irid.image_space(irid.read_image(path)[1])["space"] == space


@pytest.mark.parametrize("codes", [(9, 16, 0, 1), (9, 18, 0, 1), (1, 13, 0, 0), (1, 13, 1, 1),
                                   (22, 13, 0, 1)])
def test_cicp_codes_irid_cannot_read_are_refused_with_them(irid_cli, tmp_path, codes):
    path = tmp_path / "hdr.png"
    path.write_bytes(png_with([(b"cICP", bytes(codes))]))
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", str(path), str(tmp_path / "o.png")],
                       capture_output=True, text=True)
    assert r.returncode == 1 and f"colour primaries {codes[0]}, transfer {codes[1]}" in r.stderr, r.stderr


@pytest.mark.parametrize("damage,reason", [
    ("icc-crc", "iCCP chunk at byte 33 fails its CRC"),
    ("gama-crc", "gAMA chunk at byte 33 fails its CRC"),
    ("no-iend", "without its IEND chunk"),
    ("gama-twice", "repeats an earlier one"),
    ("gama-after-data", "follows the image data"),
    ("gama-short", "holds 3 bytes; it holds 4"),
    ("gama-zero", "gives a gamma of 0"),
])
def test_damaged_colour_chunks_are_refused_as_pngcheck_refuses(irid_cli, tmp_path, damage, reason):
    adobe = (COLORD / "AdobeRGB1998.icc").read_bytes()
    if damage == "icc-crc":
        data = bytearray(png_with([], icc_profile=adobe))
        assert data[37:41] == b"iCCP"
        length = struct.unpack(">I", data[33:37])[0]
        data[41 + length] ^= 1            # the first byte of its CRC
    elif damage == "gama-crc":
        data = bytearray(png_with([gama(0.45455)]))
        data[33 + 12 + 4 - 1] ^= 1
    elif damage == "no-iend":
        data = png_with([])[:-12]
    elif damage == "gama-twice":
        data = png_with([gama(0.45455), gama(1.0)])
    elif damage == "gama-after-data":
        data = png_with([], after_data=[gama(1.0)])
    elif damage == "gama-short":
        data = png_with([(b"gAMA", b"\0\1\0")])
    else:
        data = png_with([(b"gAMA", bytes(4))])
    path = tmp_path / f"{damage}.png"
    path.write_bytes(bytes(data))
    assert pngcheck_refuses(path)
    r = subprocess.run([irid_cli, "clip", "--method", "clamp", "--from", "srgb", str(path),
                        str(tmp_path / "o.png")], capture_output=True, text=True)
    assert r.returncode == 1 and reason in r.stderr, r.stderr
    with pytest.raises(OSError, match=reason):
        irid.read_image(path)


@pytest.mark.parametrize("red", [1e6, 1e15, 1e20, 3e38, np.inf])
@pytest.mark.parametrize("tag", ["none", "chromaticities"])
def test_a_huge_channel_stays_in_its_channel_when_the_file_is_the_target_space(irid_cli, tmp_path, red, tag):
    """An untagged EXR (linear sRGB) or one whose chromaticities are sRGB's, clipped to linear
    sRGB: no conversion at all, as with --from srgb-linear, rather than a matrix through XYZ and
    back that leaks 6e-17 of R into G and B."""
    kw = {"chromaticities": (0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329)} if tag != "none" else {}
    path = tmp_path / "huge.exr"
    irid.write_image(path, np.array([[[red, 0.0, 0.3], [0.2, 0.5, 0.7]]], np.float32), **kw)
    own, _ = clip_to_exr(irid_cli, path, tmp_path / "own.exr")
    given, _ = clip_to_exr(irid_cli, path, tmp_path / "given.exr", "--from", "srgb-linear")
    assert np.array_equal(own, given)
    assert own[0, 0].tolist() == [1.0, 0.0, pytest.approx(0.3)]

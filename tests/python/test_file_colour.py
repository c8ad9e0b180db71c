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
import struct
import subprocess

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

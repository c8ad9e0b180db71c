"""ICC-tagged images in and out, checked by readers irid did not write.

- Inputs tagged with the real profiles of Debian's colord-data, and with Display P3 and Rec.2020
  profiles built here by Little CMS itself (through ctypes), are clipped by ``irid clip``; PIL's
  ImageCms (lcms2) converts the same patches, and the two agree within 1/255.
- irid's outputs are opened by PIL, whose conversion of them agrees with irid's within 1/255;
  exiftool shows their profile descriptions; their profiles read back as the same space.
- Float: a 16-bit ProPhoto TIFF clipped to a linear EXR agrees with lcms2's float transform
  within 1e-4 (PIL has no float path; lcms2 is the library under it).
- Profiles irid cannot use are refused with the file's name and the reason.
"""

import ctypes
import io
import pathlib
import shutil
import struct
import subprocess
import zlib

import numpy as np
import pytest

import irid

COLORD = pathlib.Path("/usr/share/color/icc/colord")   # colord-data (scripts/install-deps)
RGB_PROFILES = [
    "AdobeRGB1998.icc", "AppleRGB.icc", "BestRGB.icc", "BetaRGB.icc", "Bluish.icc",
    "BruceRGB.icc", "CIE-RGB.icc", "ColorMatchRGB.icc", "DonRGB4.icc", "ECI-RGBv1.icc",
    "ECI-RGBv2.icc", "EktaSpacePS5.icc", "Gamma5000K.icc", "Gamma5500K.icc", "Gamma6500K.icc",
    "NTSC-RGB.icc", "PAL-RGB.icc", "ProPhotoRGB.icc", "Rec709.icc", "SMPTE-C-RGB.icc",
    "SwappedRedAndGreen.icc", "WideGamutRGB.icc", "sRGB.icc",
]


def patches():
    """Every code 0, 51, ..., 255 on each channel: 216 colours, (6, 36, 3) uint8."""
    levels = np.arange(0, 256, 51, dtype=np.uint8)
    grid = np.stack(np.meshgrid(levels, levels, levels, indexing="ij"), axis=-1)
    return grid.reshape(6, 36, 3)


def save_tagged(path, pixels, profile):
    from PIL import Image
    Image.fromarray(pixels).save(path, icc_profile=profile)


def pil_to_srgb(pixels, profile):
    """PIL/lcms2's relative colorimetric conversion of 8-bit codes to sRGB, unoptimised."""
    from PIL import Image, ImageCms
    src = ImageCms.ImageCmsProfile(io.BytesIO(profile))
    dst = ImageCms.ImageCmsProfile(ImageCms.createProfile("sRGB"))
    t = ImageCms.buildTransform(src, dst, "RGB", "RGB",
                                renderingIntent=ImageCms.Intent.RELATIVE_COLORIMETRIC,
                                flags=ImageCms.FLAGS["NOTPRECALC"])
    return np.asarray(ImageCms.applyTransform(Image.fromarray(pixels), t))


def read_u8(path):
    px, meta = irid.read_image(path)
    return np.round(px[..., :3] * 255).astype(np.int32), meta


def run(cli, *args, status=0):
    r = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == status, r.stderr
    return r


# --- Little CMS through ctypes: profiles built by lcms2 itself, and its float transform -------

class _XyY(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("Y", ctypes.c_double)]


def _lcms():
    lib = ctypes.CDLL("liblcms2.so.2")
    lib.cmsBuildParametricToneCurve.restype = ctypes.c_void_p
    lib.cmsBuildParametricToneCurve.argtypes = [ctypes.c_void_p, ctypes.c_int,
                                                ctypes.POINTER(ctypes.c_double)]
    lib.cmsCreateRGBProfile.restype = ctypes.c_void_p
    lib.cmsCreateRGBProfile.argtypes = [ctypes.POINTER(_XyY), ctypes.POINTER(_XyY * 3),
                                        ctypes.POINTER(ctypes.c_void_p * 3)]
    lib.cmsSaveProfileToMem.argtypes = [ctypes.c_void_p, ctypes.c_void_p,
                                        ctypes.POINTER(ctypes.c_uint32)]
    lib.cmsOpenProfileFromMem.restype = ctypes.c_void_p
    lib.cmsOpenProfileFromMem.argtypes = [ctypes.c_char_p, ctypes.c_uint32]
    lib.cmsCreateTransform.restype = ctypes.c_void_p
    lib.cmsCreateTransform.argtypes = [ctypes.c_void_p, ctypes.c_uint32, ctypes.c_void_p,
                                       ctypes.c_uint32, ctypes.c_uint32, ctypes.c_uint32]
    lib.cmsDoTransform.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p,
                                   ctypes.c_uint32]
    lib.cmsCloseProfile.argtypes = [ctypes.c_void_p]
    lib.cmsDeleteTransform.argtypes = [ctypes.c_void_p]
    lib.cmsFreeToneCurve.argtypes = [ctypes.c_void_p]
    return lib


def lcms_rgb_profile(primaries, white, curve_type, params):
    """An RGB profile built by lcms2's cmsCreateRGBProfile (its curve types: 1 = ICC type 0,
    4 = ICC type 3), as bytes."""
    lib = _lcms()
    p = (ctypes.c_double * len(params))(*params)
    curve = lib.cmsBuildParametricToneCurve(None, curve_type, p)
    w = _XyY(white[0], white[1], 1.0)
    prim = (_XyY * 3)(*[_XyY(x, y, 1.0) for x, y in primaries])
    curves = (ctypes.c_void_p * 3)(curve, curve, curve)
    h = lib.cmsCreateRGBProfile(ctypes.byref(w), ctypes.byref(prim), ctypes.byref(curves))
    n = ctypes.c_uint32(0)
    assert lib.cmsSaveProfileToMem(h, None, ctypes.byref(n))
    buf = ctypes.create_string_buffer(n.value)
    assert lib.cmsSaveProfileToMem(h, buf, ctypes.byref(n))
    lib.cmsCloseProfile(h)
    lib.cmsFreeToneCurve(curve)
    return buf.raw[:n.value]


def lcms_float(src_profile, dst_profile, rgb, src_format):
    """lcms2's relative colorimetric transform of `rgb` (uint16 or float32 triples) to float."""
    lib = _lcms()
    # lcms2.h: TYPE_RGB_16 = COLORSPACE_SH(PT_RGB) | CHANNELS_SH(3) | BYTES_SH(2); TYPE_RGB_FLT
    # adds FLOAT_SH(1) with 4 bytes.
    formats = {"u16": (4 << 16) | (3 << 3) | 2, "f32": (1 << 22) | (4 << 16) | (3 << 3) | 4}
    s = lib.cmsOpenProfileFromMem(src_profile, len(src_profile))
    d = lib.cmsOpenProfileFromMem(dst_profile, len(dst_profile))
    # INTENT_RELATIVE_COLORIMETRIC = 1; cmsFLAGS_NOOPTIMIZE = 0x0100... is NOTPRECALC; 0x0100.
    t = lib.cmsCreateTransform(s, formats[src_format], d, formats["f32"], 1, 0x0100)
    src = np.ascontiguousarray(rgb)
    out = np.zeros(src.shape, np.float32)
    lib.cmsDoTransform(t, src.ctypes.data, out.ctypes.data, src.size // 3)
    lib.cmsDeleteTransform(t)
    lib.cmsCloseProfile(s)
    lib.cmsCloseProfile(d)
    return out


# Display P3 (SMPTE EG 432-1, D65, the sRGB curve) and Rec.2020 (ITU-R BT.2020-2 Table 3 and
# Table 4's curve, inverted: ICC type 3 with g 1/0.45, a 1/α, b (α-1)/α, c 1/4.5, d 4.5 β).
SRGB_CURVE = (2.4, 1 / 1.055, 0.055 / 1.055, 1 / 12.92, 0.04045)
ALPHA, BETA = 1.09929682680944, 0.018053968510807
BT2020_CURVE = (1 / 0.45, 1 / ALPHA, (ALPHA - 1) / ALPHA, 1 / 4.5, 4.5 * BETA)
P3 = ((0.680, 0.320), (0.265, 0.690), (0.150, 0.060))
REC2020 = ((0.708, 0.292), (0.170, 0.797), (0.131, 0.046))
D65 = (0.3127, 0.3290)


# --- inputs ---------------------------------------------------------------------------------

def clip_tagged(cli, tmp_path, profile):
    """The patches tagged with `profile` (TIFF), through `irid clip --method clamp --to srgb`:
    irid's result and PIL's conversion of the same patches, as int codes."""
    px = patches()
    save_tagged(tmp_path / "in.tif", px, profile)
    r = run(cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / "in.tif",
            tmp_path / "out.png")
    assert "no ICC profile" not in r.stderr
    got, _ = read_u8(tmp_path / "out.png")
    return got, pil_to_srgb(px, profile).astype(np.int32)


@pytest.mark.parametrize("name", RGB_PROFILES)
def test_colord_tagged_tiff_is_clipped_as_pil_converts_it(irid_cli, tmp_path, name):
    got, want = clip_tagged(irid_cli, tmp_path, (COLORD / name).read_bytes())
    assert np.abs(got - want).max() <= 1, name
    # The output names its space to PIL too.
    from PIL import Image, ImageCms
    with Image.open(tmp_path / "out.png") as im:
        desc = ImageCms.getProfileDescription(ImageCms.ImageCmsProfile(io.BytesIO(im.info["icc_profile"])))
    assert desc.strip() == "srgb (irid)"


@pytest.mark.parametrize("fmt", ["png", "jpg"])
def test_adobe_rgb_png_and_jpeg_take_their_space_from_the_profile(irid_cli, tmp_path, fmt):
    profile = (COLORD / "AdobeRGB1998.icc").read_bytes()
    px = patches()
    from PIL import Image
    Image.fromarray(px).save(tmp_path / f"in.{fmt}", icc_profile=profile, quality=95)
    run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / f"in.{fmt}",
        tmp_path / "out.png")
    # JPEG decoders differ by a code here and there: convert the codes irid read.
    stored, _ = irid.read_image(tmp_path / f"in.{fmt}")
    codes = np.round(stored * 255).astype(np.uint8)
    got, _ = read_u8(tmp_path / "out.png")
    assert np.abs(got - pil_to_srgb(codes, profile).astype(np.int32)).max() <= 1
    # Taken as sRGB instead, the result would differ: the profile was used.
    run(irid_cli, "clip", "--method", "clamp", "--from", "srgb", "--to", "srgb",
        tmp_path / f"in.{fmt}", tmp_path / "as-srgb.png")
    wrong, _ = read_u8(tmp_path / "as-srgb.png")
    assert np.abs(wrong - got).max() > 20


@pytest.mark.parametrize("space,primaries,curve,builtin", [
    ("display-p3", P3, SRGB_CURVE, "display-p3"),
    ("rec2020", REC2020, BT2020_CURVE, "rec2020"),
])
def test_lcms_built_p3_and_rec2020_profiles(irid_cli, tmp_path, space, primaries, curve, builtin):
    profile = lcms_rgb_profile(primaries, D65, 4, curve)
    info = irid.read_icc_profile(profile)
    assert info["exact"] and info["space"] == builtin
    px = patches()
    save_tagged(tmp_path / "in.tif", px, profile)
    run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / "in.tif",
        tmp_path / "out.png")
    got, _ = read_u8(tmp_path / "out.png")
    assert np.abs(got - pil_to_srgb(px, profile).astype(np.int32)).max() <= 1
    # In-gamut colours clipped into the profile's own space come back as they were.
    run(irid_cli, "clip", "--method", "smits", "--to", space, tmp_path / "in.tif",
        tmp_path / "same.tif")
    same, meta = read_u8(tmp_path / "same.tif")
    assert np.array_equal(same, px.astype(np.int32))


def test_float_output_matches_lcms_float_transform(irid_cli, tmp_path):
    """A 16-bit ProPhoto TIFF → linear sRGB EXR, against lcms2's float transform to a linear
    sRGB profile it built itself, clamped as the clamp method clamps: within 1e-4."""
    profile = (COLORD / "ProPhotoRGB.icc").read_bytes()
    rng = np.random.default_rng(7)
    codes = rng.integers(0, 65536, (16, 16, 3), dtype=np.uint16)
    irid.write_image(tmp_path / "in.tif", codes / 65535.0, bits=16, icc_profile=profile)
    run(irid_cli, "clip", "--method", "clamp", "--to", "srgb-linear", tmp_path / "in.tif",
        tmp_path / "out.exr")
    got, meta = irid.read_image(tmp_path / "out.exr")
    linear = lcms_rgb_profile(((0.64, 0.33), (0.30, 0.60), (0.15, 0.06)), D65, 1, (1.0,))
    want = np.clip(lcms_float(profile, linear, codes.reshape(-1, 3), "u16"), 0, 1)
    assert np.abs(got.reshape(-1, 3) - want).max() < 1e-4
    assert irid.image_space(meta)["space"] == "srgb-linear"


def test_untagged_integer_image_is_srgb_and_said_so(irid_cli, tmp_path):
    px = patches()
    from PIL import Image
    Image.fromarray(px).save(tmp_path / "in.png")
    r = run(irid_cli, "clip", "--method", "smits", "--to", "srgb", tmp_path / "in.png",
            tmp_path / "out.png")
    assert "in.png has no ICC profile; its values are taken as sRGB" in r.stderr
    got, _ = read_u8(tmp_path / "out.png")
    assert np.array_equal(got, px.astype(np.int32))


def test_exr_chromaticities_define_the_source(irid_cli, tmp_path):
    rng = np.random.default_rng(3)
    rgb = rng.uniform(0, 1.5, (8, 8, 3)).astype(np.float32)
    irid.write_image(tmp_path / "in.exr", rgb, color_space="acescg-linear")
    _, meta = irid.read_image(tmp_path / "in.exr")
    assert meta["chromaticities"] == pytest.approx((0.713, 0.293, 0.165, 0.830, 0.128, 0.044,
                                                    0.32168, 0.33767), abs=1e-7)
    run(irid_cli, "clip", "--method", "oklab", "--to", "srgb-linear", tmp_path / "in.exr",
        tmp_path / "file.exr")
    run(irid_cli, "clip", "--method", "oklab", "--from", "acescg-linear", "--to", "srgb-linear",
        tmp_path / "in.exr", tmp_path / "given.exr")
    a, ma = irid.read_image(tmp_path / "file.exr")
    b, _ = irid.read_image(tmp_path / "given.exr")
    assert np.array_equal(a, b)
    # The output carries the destination's chromaticities, read back by OpenImageIO's oiiotool.
    assert ma["chromaticities"] == pytest.approx((0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127,
                                                  0.3290), abs=1e-7)
    assert ma["adopted_neutral"] is None
    run(irid_cli, "clip", "--method", "clamp", "--to", "acescg", tmp_path / "in.exr",
        tmp_path / "aces.exr")
    _, mc = irid.read_image(tmp_path / "aces.exr")
    assert mc["adopted_neutral"] == pytest.approx((0.32168, 0.33767), abs=1e-7)
    info = subprocess.run(["oiiotool", "--info", "-v", str(tmp_path / "aces.exr")],
                          capture_output=True, text=True, check=True).stdout
    assert "chromaticities: 0.713, 0.293, 0.165, 0.83, 0.128, 0.044, 0.32168, 0.33767" in info


# --- outputs --------------------------------------------------------------------------------

@pytest.mark.parametrize("space,primaries,white,curve", [
    ("display-p3", P3, D65, SRGB_CURVE),
    ("rec2020", REC2020, D65, BT2020_CURVE),
    ("adobe-rgb", ((0.64, 0.33), (0.21, 0.71), (0.15, 0.06)), D65, (563 / 256,)),
    ("ntsc1953", ((0.67, 0.33), (0.21, 0.71), (0.14, 0.08)), (0.310, 0.316), (2.2,)),
])
@pytest.mark.parametrize("fmt", ["png", "tif"])
def test_outputs_carry_a_profile_other_readers_use(irid_cli, tmp_path, space, primaries, white,
                                                    curve, fmt):
    px = patches()
    save_tagged(tmp_path / "in.tif", px, (COLORD / "sRGB.icc").read_bytes())
    out = tmp_path / f"out.{fmt}"
    run(irid_cli, "clip", "--method", "clamp", "--to", space, tmp_path / "in.tif", out)
    codes, meta = read_u8(out)
    profile = meta["icc_profile"]
    assert profile is not None
    # PIL converts irid's output to sRGB as irid itself does (irid reading its own file).
    run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", out, tmp_path / "back.png")
    back, _ = read_u8(tmp_path / "back.png")
    pil = pil_to_srgb(codes.astype(np.uint8), profile).astype(np.int32)
    assert np.abs(back - pil).max() <= 1
    # exiftool reads the profile: its description and version.
    tags = subprocess.run(["exiftool", "-s3", "-ProfileDescription", "-ProfileVersion",
                           "-ProfileClass", str(out)],
                          capture_output=True, text=True, check=True).stdout.splitlines()
    assert tags == [f"{space} (irid)", "4.3.0", "Display Device Profile"]
    # Its profile ID is the MD5 of the profile with the flags, intent and ID fields zeroed
    # (ICC.1:2022 §7.2.18), and the same space always gives the same bytes.
    import hashlib
    zeroed = bytearray(profile)
    for lo, hi in ((44, 48), (64, 68), (84, 100)):
        zeroed[lo:hi] = bytes(hi - lo)
    assert hashlib.md5(bytes(zeroed)).digest() == profile[84:100]
    assert profile == irid.icc_profile(space)
    # Round trip: the primaries, white and curve, to 1e-4.
    info = irid.read_icc_profile(profile)
    assert info["space"] == space
    for got, want in zip(info["primaries"], primaries):
        assert got == pytest.approx(want, abs=1e-4)
    assert info["white"] == pytest.approx(white, abs=1e-4)
    params = info["transfer"]["parameters"]
    want = (curve + (1.0, 0.0, 0.0, 0.0, 0.0, 0.0))[:7] if len(curve) == 1 else curve + (0.0, 0.0)
    assert params == pytest.approx(want, abs=1e-4)


def test_jpeg_output_carries_the_profile(irid_cli, tmp_path):
    save_tagged(tmp_path / "in.tif", patches(), (COLORD / "sRGB.icc").read_bytes())
    run(irid_cli, "clip", "--method", "clamp", "--to", "display-p3", tmp_path / "in.tif",
        tmp_path / "out.jpg")
    from PIL import Image, ImageCms
    with Image.open(tmp_path / "out.jpg") as im:
        assert im.format == "JPEG" and im.mode == "RGB"
        prof = ImageCms.ImageCmsProfile(io.BytesIO(im.info["icc_profile"]))
    assert ImageCms.getProfileDescription(prof).strip() == "display-p3 (irid)"
    tags = subprocess.run(["exiftool", "-s3", "-ProfileDescription", str(tmp_path / "out.jpg")],
                          capture_output=True, text=True, check=True).stdout.strip()
    assert tags == "display-p3 (irid)"
    r = run(irid_cli, "clip", "--method", "clamp", "--bits", "16", tmp_path / "in.tif",
            tmp_path / "deep.jpg", status=2)
    assert "JPEG holds 8 bits" in r.stderr
    rgba = np.zeros((2, 2, 4), np.float32)
    with pytest.raises(OSError, match="JPEG holds 1 .grey. or 3 .RGB., no alpha"):
        irid.write_image(tmp_path / "a.jpg", rgba)
    with pytest.raises(KeyError, match="jpeg:QUALITY"):
        irid.write_image(tmp_path / "a.jpg", rgba[..., :3], compression="jpeg:101")
    irid.write_image(tmp_path / "q.jpg", np.full((8, 8, 3), 0.5), compression="jpeg:50")
    assert not (tmp_path / "a.jpg").exists() and (tmp_path / "q.jpg").exists()


def test_python_write_image_tags_and_read_image_reports(tmp_path):
    rgb = np.full((2, 2, 3), 0.5, np.float32)
    irid.write_image(tmp_path / "p3.png", rgb, color_space="display-p3")
    _, meta = irid.read_image(tmp_path / "p3.png")
    assert irid.read_icc_profile(meta["icc_profile"])["description"] == "display-p3 (irid)"
    s = irid.image_space(meta)
    assert s["space"] == "display-p3" and s["encoded"] and not s["assumed"] and s["exact"]
    irid.write_image(tmp_path / "plain.png", rgb, color_space="display-p3", tag=False)
    _, plain = irid.read_image(tmp_path / "plain.png")
    assert plain["icc_profile"] is None and irid.image_space(plain)["assumed"]
    # A -linear name's profile has a linear curve (what such values are).
    lin = irid.read_icc_profile(irid.icc_profile("rec2020-linear"))
    assert lin["transfer"]["parameters"][:3] == pytest.approx((1.0, 1.0, 0.0), abs=1e-4)
    assert lin["primaries"][0] == pytest.approx(REC2020[0], abs=1e-4)
    with pytest.raises(ValueError, match="EXR files carry chromaticities"):
        irid.write_image(tmp_path / "x.exr", rgb, icc_profile=irid.icc_profile("srgb"))
    with pytest.raises(ValueError, match="only EXR"):
        irid.write_image(tmp_path / "x.png", rgb, chromaticities=[0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329])
    with pytest.raises(ValueError, match="ICC profile"):
        irid.write_image(tmp_path / "x.png", rgb, icc_profile=b"\0" * 200)
    assert not (tmp_path / "x.png").exists() and not (tmp_path / "x.exr").exists()


def test_python_clip_image_takes_the_files_space(irid_cli, tmp_path):
    profile = (COLORD / "WideGamutRGB.icc").read_bytes()
    save_tagged(tmp_path / "in.tif", patches(), profile)
    run(irid_cli, "clip", "--method", "oklab", "--to", "srgb", tmp_path / "in.tif",
        tmp_path / "cli.tif")
    px, meta = irid.read_image(tmp_path / "in.tif")
    assert irid.image_space(meta)["space"] is None    # Wide Gamut RGB is none of irid's spaces
    out, _ = irid.clip_image(px, meta["channels"], "oklab", source=meta, target="srgb",
                             encode=True)
    cli, _ = irid.read_image(tmp_path / "cli.tif")
    assert np.abs(np.round(out * 255) - np.round(cli * 255)).max() == 0


# --- LUT profiles, and profiles that carry a LUT beside their matrix -------------------------

def icc_tags(profile):
    """(signature, data) of each tag (ICC.1:2022 §7.3)."""
    import struct
    count = struct.unpack(">I", profile[128:132])[0]
    out = []
    for i in range(count):
        sig, off, n = struct.unpack(">4sII", profile[132 + 12 * i:144 + 12 * i])
        out.append((sig, profile[off:off + n]))
    return out


def icc_assemble(header, tags):
    """A profile of `header`'s first 128 bytes and these tags, 4-byte aligned, sizes set."""
    import struct
    table = 132 + 12 * len(tags)
    data, entries, at = b"", b"", table
    for sig, body in tags:
        pad = (-len(body)) % 4
        entries += struct.pack(">4sII", sig, at, len(body))
        data += body + b"\0" * pad
        at += len(body) + pad
    head = bytearray(header[:128])
    head[0:4] = struct.pack(">I", table + len(data))
    head[84:100] = bytes(16)   # no profile ID: it would no longer match
    return bytes(head) + struct.pack(">I", len(tags)) + entries + data


def lcms_link_as_profile(pcs):
    """An RGB profile whose only transform is an A2B0 table: lcms2's device link from its own
    sRGB to Lab or XYZ (cmsTransform2DeviceLink), relabelled a display profile."""
    lib = _lcms()
    for name, args in (("cmsCreate_sRGBProfile", []), ("cmsCreateLab4Profile", [ctypes.c_void_p]),
                       ("cmsCreateXYZProfile", [])):
        getattr(lib, name).restype = ctypes.c_void_p
        getattr(lib, name).argtypes = args
    lib.cmsTransform2DeviceLink.restype = ctypes.c_void_p
    lib.cmsTransform2DeviceLink.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_uint32]
    src = lib.cmsCreate_sRGBProfile()
    dst = lib.cmsCreateLab4Profile(None) if pcs == "lab" else lib.cmsCreateXYZProfile()
    # lcms2.h: TYPE_RGB_16, TYPE_Lab_16 (PT_Lab = 10), TYPE_XYZ_16 (PT_XYZ = 9).
    out_format = ((10 if pcs == "lab" else 9) << 16) | (3 << 3) | 2
    t = lib.cmsCreateTransform(src, (4 << 16) | (3 << 3) | 2, dst, out_format, 1, 0)
    link = lib.cmsTransform2DeviceLink(t, 4.3, 0)
    n = ctypes.c_uint32(0)
    assert lib.cmsSaveProfileToMem(link, None, ctypes.byref(n))
    buf = ctypes.create_string_buffer(n.value)
    assert lib.cmsSaveProfileToMem(link, buf, ctypes.byref(n))
    profile = bytearray(buf.raw[:n.value])
    profile[12:16] = b"mntr"   # ICC.1 §7.2.5: the class
    return bytes(profile)


@pytest.mark.parametrize("pcs", ["lab", "xyz"])
def test_lut_profile_goes_through_little_cms_as_pil_does(irid_cli, tmp_path, pcs):
    profile = lcms_link_as_profile(pcs)
    info = irid.read_icc_profile(profile)
    assert not info["exact"] and info["reason"] == "a LUT-based profile"
    got, pil = clip_tagged(irid_cli, tmp_path, profile)
    assert np.abs(got - pil).max() <= 1
    # The table is sRGB's: black stays black (no black-point compensation), grey stays grey.
    assert np.abs(got - patches().astype(np.int32)).max() <= 1


def test_an_a2b0_table_beside_the_matrix_takes_precedence(irid_cli, tmp_path):
    # Adobe RGB's matrix/TRC tags with an A2B0 table of sRGB (DisplayCAL's "XYZ LUT + matrix"
    # profiles carry both): every CMM uses the table (ICC.1:2022 §8.4), and so must irid.
    adobe = (COLORD / "AdobeRGB1998.icc").read_bytes()
    a2b0 = dict(icc_tags(lcms_link_as_profile("xyz")))[b"A2B0"]
    hybrid = icc_assemble(adobe, icc_tags(adobe) + [(b"A2B0", a2b0)])
    assert irid.read_icc_profile(hybrid)["reason"] == "a LUT-based profile"
    got, pil = clip_tagged(irid_cli, tmp_path, hybrid)
    assert np.abs(got - pil).max() <= 1
    assert np.abs(got - patches().astype(np.int32)).max() <= 1   # sRGB's table, not Adobe's


def test_a_profile_named_like_a_builtin_space_is_not_taken_for_it(tmp_path):
    wide = (COLORD / "WideGamutRGB.icc").read_bytes()
    tags = [(sig, body) for sig, body in icc_tags(wide) if sig != b"desc"]
    named = icc_assemble(wide, tags + [(b"desc", dict(icc_tags(irid.icc_profile("srgb")))[b"desc"])])
    assert irid.read_icc_profile(named)["description"] == "srgb (irid)"
    save_tagged(tmp_path / "in.tif", patches(), named)
    _, meta = irid.read_image(tmp_path / "in.tif")
    s = irid.image_space(meta)
    assert s["space"] is None and s["exact"]


# --- refusals -------------------------------------------------------------------------------

def patched(offset, value):
    p = bytearray((COLORD / "sRGB.icc").read_bytes())
    p[offset:offset + len(value)] = value
    return bytes(p)


@pytest.mark.parametrize("profile,reason,readable", [
    ((COLORD / "Crayons.icc").read_bytes(), "a named-colour profile", True),
    (patched(16, b"CMYK"), "a CMYK profile", True),    # ICC.1 §7.2.6, the data colour space
    (patched(12, b"link"), "a device link", True),      # §7.2.5, the profile class
    (patched(12, b"abst"), "an abstract profile", True),
    (patched(36, b"xxxx"), "cannot be read", True),     # §7.2.9, the 'acsp' signature
    # Cut short: refused before OpenImageIO reads its tags (which it does unchecked), so not
    # even --from can take the file.
    ((COLORD / "sRGB.icc").read_bytes()[:400], "truncated", False),
])
def test_unusable_profiles_are_refused_with_file_and_reason(irid_cli, tmp_path, profile, reason,
                                                           readable):
    save_tagged(tmp_path / "bad.tif", patches(), profile)
    r = run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / "bad.tif",
            tmp_path / "out.png", status=1)
    assert f"{tmp_path / 'bad.tif'}: ICC profile: {reason}" in r.stderr
    assert not (tmp_path / "out.png").exists()
    if not readable:
        with pytest.raises(OSError, match=reason):
            irid.read_image(tmp_path / "bad.tif")
        return
    # --from overrides the file, and says what it overrode.
    r = run(irid_cli, "clip", "--method", "clamp", "--from", "srgb", "--to", "srgb",
            tmp_path / "bad.tif", tmp_path / "out.png")
    assert "--from srgb overrides what" in r.stderr and reason in r.stderr
    _, meta = irid.read_image(tmp_path / "bad.tif")
    with pytest.raises(ValueError, match=reason):
        irid.image_space(meta)


def test_tone_curves_that_decode_nothing_are_refused(irid_cli, tmp_path):
    # A reversed table would invert the image, a γ of 0 make it white: refused, not applied.
    import struct
    srgb = (COLORD / "sRGB.icc").read_bytes()
    reversed_curve = b"curv" + bytes(4) + struct.pack(">IHH", 2, 65535, 0)
    flat = b"curv" + bytes(4) + struct.pack(">IHH", 2, 30000, 30000)
    zero_gamma = b"curv" + bytes(4) + struct.pack(">IH", 1, 0) + bytes(2)
    for curve, reason in ((reversed_curve, "below the one before it"), (flat, "do not rise"),
                          (zero_gamma, "g = 0")):
        tags = [(sig, curve if sig in (b"rTRC", b"gTRC", b"bTRC") else body)
                for sig, body in icc_tags(srgb)]
        save_tagged(tmp_path / "bad.tif", patches(), icc_assemble(srgb, tags))
        r = run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / "bad.tif",
                tmp_path / "out.png", status=1)
        assert "ICC profile: its red tone curve is no decoding of image values" in r.stderr
        assert reason in r.stderr


@pytest.mark.parametrize("fmt", ["tif", "jpg"])
def test_a_tag_past_the_profiles_end_is_refused_before_openimageio_reads_it(irid_cli, tmp_path,
                                                                            fmt):
    # A tag offset near 2^32 (offset + size wraps): OpenImageIO 2.4 reads TIFF and JPEG
    # profiles' tags unchecked and would crash; irid checks the table first.
    import struct
    p = bytearray((COLORD / "sRGB.icc").read_bytes())
    p[132 + 4:132 + 8] = struct.pack(">I", 0xFFFFFFF8)
    save_tagged(tmp_path / f"bad.{fmt}", patches(), bytes(p))
    r = run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / f"bad.{fmt}",
            tmp_path / "out.png", status=1)
    assert "ICC profile: damaged: tag 0 ('desc') at byte 4294967288" in r.stderr
    with pytest.raises(OSError, match="runs past the profile"):
        irid.read_image(tmp_path / f"bad.{fmt}")


def test_a_png_profile_string_past_its_end_is_refused(irid_cli, tmp_path):
    # The image harness's finding png-3 (docs/RELIABILITY.md): an mluc string offset past the
    # profile, which libpng passes and OpenImageIO 2.4 read out of bounds.
    # The fuzzer's file also fails its iCCP chunk's CRC, which is refused first; with its CRC
    # made whole the profile's own check speaks.
    png = pathlib.Path(__file__).resolve().parents[1] / "fuzz/regressions/image/png-iccp-tag-past-end-oiio-segv.png"
    r = run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", png, tmp_path / "out.png",
            status=1)
    assert "its iCCP chunk at byte 33 fails its CRC" in r.stderr
    data = bytearray(png.read_bytes())
    assert data[37:41] == b"iCCP"
    length = struct.unpack(">I", data[33:37])[0]
    data[41 + length:45 + length] = struct.pack(">I", zlib.crc32(bytes(data[37:41 + length])))
    (tmp_path / "crc-whole.png").write_bytes(data)
    r = run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / "crc-whole.png",
            tmp_path / "out.png", status=1)
    assert "ICC profile: damaged: tag 1 ('cprt') has a string of 48 bytes" in r.stderr


def test_grey_images_are_written_without_an_rgb_profile(tmp_path):
    grey = np.full((4, 4), 0.5, np.float32)
    for ext in ("png", "tif", "jpg"):
        irid.write_image(tmp_path / f"g.{ext}", grey, color_space="srgb")
        _, meta = irid.read_image(tmp_path / f"g.{ext}")
        assert meta["icc_profile"] is None


def test_odd_metadata_is_refused_by_name(tmp_path):
    with pytest.raises(ValueError, match="chromaticities"):
        irid.write_image(tmp_path / "x.exr", np.zeros((2, 2, 3)), chromaticities=5)
    with pytest.raises(ValueError, match="chromaticities"):
        irid.write_image(tmp_path / "x.exr", np.zeros((2, 2, 3)), chromaticities="abc")
    with pytest.raises(ValueError, match="'integer'"):
        irid.image_space({"integer": "no", "icc_profile": None, "chromaticities": None})
    with pytest.raises(ValueError, match="8 .red, green, blue and white"):
        irid.image_space({"integer": False, "icc_profile": None, "chromaticities": (0.3, 0.3)})


def test_png_profile_that_libpng_drops_is_not_ignored(irid_cli, tmp_path):
    save_tagged(tmp_path / "bad.png", patches(), patched(16, b"CMYK"))
    r = run(irid_cli, "clip", "--method", "clamp", "--to", "srgb", tmp_path / "bad.png",
            tmp_path / "out.png", status=1)
    assert "bad.png: ICC profile: damaged: libpng rejected it" in r.stderr
    _, meta = irid.read_image(tmp_path / "bad.png")
    assert meta["icc_profile_rejected"]

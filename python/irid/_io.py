"""Images and ICC profiles: reading and writing files through OpenImageIO, what they say."""

from __future__ import annotations

import numbers
import os

import numpy as np

from . import _irid
from ._args import _flag, _floats, _name, _path, _text

__all__ = [
    "icc_profile",
    "image_space",
    "read_icc_profile",
    "read_image",
    "write_image",
]


def _file_facts(metadata):
    """read_image's metadata, its types checked, for the library's decisions."""
    try:
        icc = metadata.get("icc_profile")
        chroma = metadata.get("chromaticities")
        integer = metadata["integer"]
    except (KeyError, AttributeError):
        raise ValueError("source: a dict is the metadata read_image returns (with 'integer', "
                         "'icc_profile' and 'chromaticities')") from None
    if icc is not None and not isinstance(icc, (bytes, bytearray)):
        raise ValueError("source: 'icc_profile' must be bytes or None")
    # Older metadata without "bits": an integer file's 8, a float file's 32.
    bits = metadata.get("bits", 8 if metadata.get("integer") else 32)
    if isinstance(bits, bool) or not isinstance(bits, numbers.Integral) or not 1 <= bits <= 64:
        raise ValueError(f"source: 'bits' {bits!r} is not a whole number of bits")
    return {
        "icc_profile": None if icc is None else bytes(icc),
        "chromaticities": None if chroma is None else _floats(chroma, "source: 'chromaticities'"),
        "integer": _flag(integer, "source: 'integer'"),
        "bits": int(bits),
        "icc_profile_rejected": _flag(metadata.get("icc_profile_rejected", False),
                                      "source: 'icc_profile_rejected'"),
        "icc_profile_damage": _text(metadata.get("icc_profile_damage") or "",
                                    "source: 'icc_profile_damage'"),
        "cmyk": _flag(metadata.get("cmyk", False), "source: 'cmyk'"),
        "model": _text(metadata.get("model") or "", "source: 'model'") or None,
        "png": _png_facts(metadata.get("png")),
    }


def _png_facts(png):
    """read_image's "png" entry checked: None, or a dict of "srgb" (bool), "gamma" (> 0),
    "chromaticities" (8 numbers) and "cicp" (4 codes of 0 to 255)."""
    if png is None:
        return None
    if not isinstance(png, dict) or not set(png) <= {"srgb", "gamma", "chromaticities", "cicp"}:
        raise ValueError("source: 'png' is None or a dict of 'srgb', 'gamma', 'chromaticities', 'cicp'")
    out = {}
    if "srgb" in png:
        out["srgb"] = _flag(png["srgb"], "source: png 'srgb'")
    if "gamma" in png:
        g = png["gamma"]
        if isinstance(g, bool) or not isinstance(g, numbers.Real) or not g > 0:
            raise ValueError(f"source: png 'gamma' {g!r} is not a number above 0")
        out["gamma"] = float(g)
    if "chromaticities" in png:
        out["chromaticities"] = _floats(png["chromaticities"], "source: png 'chromaticities'")
    if "cicp" in png:
        codes = png["cicp"]
        if (not isinstance(codes, (list, tuple)) or len(codes) != 4 or
                any(isinstance(c, bool) or not isinstance(c, numbers.Integral) or not 0 <= c <= 255
                    for c in codes)):
            raise ValueError("source: png 'cicp' is 4 codes of 0 to 255")
        out["cicp"] = [int(c) for c in codes]
    return out


def image_space(metadata):
    """What an image file says about the space of its values, from :func:`read_image`'s
    metadata: its ICC profile, else its EXR chromaticities, else the assumption (sRGB for an
    integer file, linear sRGB for a float one).

    Returns a dict: "space" (the name to give as ``source``, e.g. "adobe-rgb", "acescg-linear";
    for a space that is none of irid's built-in ones, or a profile taken through Little CMS,
    None: pass the metadata itself as ``clip_image(..., source=metadata)``), "origin" (where it
    came from, in words), "assumed" (the file said nothing), "encoded" (values carry the curve),
    "exact" (matrix/TRC or chromaticities, not through Little CMS). Raises ValueError for a
    profile irid cannot use (corrupt, CMYK, a device link, ...).

    An untagged 8-bit file is taken as sRGB:

    >>> import irid
    >>> facts = irid.image_space({"integer": True, "icc_profile": None, "chromaticities": None})
    >>> facts["space"], facts["assumed"], facts["encoded"]
    ('srgb', True, True)
    """
    f = _irid.FileSpace(_file_facts(metadata))
    return {"space": f.space, "origin": f.origin, "assumed": f.assumed, "encoded": f.encoded,
            "exact": f.exact}


def icc_profile(space, description=""):
    """The ICC profile (version 4.3, display class, matrix/TRC, built by Little CMS) of one of
    irid's RGB spaces ("display-p3", "rec2020", ...), as bytes: what irid embeds in the PNG and
    TIFF files it writes. description: the profile's description ("" for "NAME (irid)").

    >>> import irid
    >>> profile = irid.icc_profile("display-p3")
    >>> profile[36:40]                  # the ICC signature
    b'acsp'
    >>> irid.read_icc_profile(profile)["description"]
    'display-p3 (irid)'
    """
    return _irid.icc_profile(_name(space, "space"), _text(description, "description"))


def read_icc_profile(data):
    """What an ICC profile says, as irid reads it (irid/exchange/icc.h): a dict with
    "description", "version", "exact" (a matrix/TRC profile with one curve, taken exactly),
    "reason" (why not, otherwise), "space" (the built-in space it is, or None), "primaries"
    ((x, y) of red, green, blue), "white" (x, y) and "transfer" ({"kind": "parametric",
    "parameters": (g, a, b, c, d, e, f)} in ICC.1's type-4 form, or {"kind": "sampled",
    "samples": (...)}); the last four None for a profile that is not exact. Raises ValueError
    for a profile irid cannot use, with the reason.

    >>> import irid
    >>> info = irid.read_icc_profile(irid.icc_profile("rec2020"))
    >>> info["space"], info["version"], info["exact"], info["transfer"]["kind"]
    ('rec2020', '4.3', True, 'parametric')
    >>> [round(v, 3) for v in info["white"]]
    [0.313, 0.329]
    """
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise ValueError(f"data: {type(data).__name__}; an ICC profile is bytes")
    return _irid.read_icc_profile(bytes(data))


def read_image(path):
    """Reads an image through OpenImageIO (EXR, TIFF, PNG, JPEG, HDR, ...).

    Returns (pixels, metadata): pixels float32 of shape (height, width, channels), as stored
    (8- and 16-bit files scaled to [0, 1] and still encoded: decode them with
    ``convert(..., "srgb", "srgb-linear")`` or the space they are in); metadata a dict with
    "channels" (names), "color_space" (irid's or OpenImageIO's name, may be empty),
    "description", "bits" (per sample as stored), "integer" (stored as integers),
    "icc_profile" (the embedded ICC profile's bytes, or None; "icc_profile_rejected" is True when
    the file had one that is damaged, and "icc_profile_damage" says how, else None),
    "chromaticities" (an EXR's 8 values, or None), "adopted_neutral" (an EXR's x, y, or None),
    "data_window" and "display_window" (where the pixels sit and the frame, as inclusive boxes
    x min, y min, x max, y max: an EXR's windows; 0, 0, width - 1, height - 1 for a file without),
    "png" (a PNG's colour chunks besides iCCP, or None: "srgb", "gamma" of gAMA, "chromaticities"
    of cHRM as red, green, blue, white x, y, "cicp" the 4 codes of cICP), "cmyk" (the file
    stores CMYK or YCCK) and "model" (the colour model OpenImageIO converted to
    RGB without a profile: "CMYK", "YCCK", "CIELab", "ICCLab", "ITULab"; None for the file's own
    RGB or grey, which are then as stored). :func:`image_space` says what space they name.
    Raises OSError for a file that cannot be read whole (missing, not an image, truncated or
    corrupt pixel data, a header declaring more than the file holds, larger than 64 Mpixel).

    >>> import os, tempfile, numpy as np, irid
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = os.path.join(folder, "one.exr")
    ...     irid.write_image(path, np.array([[[2.0, 0.5, 0.25]]]), color_space="acescg-linear")
    ...     pixels, metadata = irid.read_image(path)
    >>> pixels.dtype, pixels.tolist()
    (dtype('float32'), [[[2.0, 0.5, 0.25]]])
    >>> metadata["channels"], metadata["bits"], irid.image_space(metadata)["space"]
    (['R', 'G', 'B'], 32, 'acescg-linear')
    """
    return _irid.read_image(_path(path))


def write_image(path, array, channels=None, color_space="", description="", bits=8,
                compression="", tag=True, icc_profile=None, chromaticities=None, data_window=None,
                display_window=None):
    """Writes an image; the format follows the extension (.exr: 32-bit float, linear values;
    .png, .tif/.tiff: ``bits`` 8 or 16, encoded values in [0, 1]; .jpg/.jpeg: 8 bits, 1 or 3
    channels, quality 95 unless ``compression="jpeg:Q"``).

    array: (height, width) or (height, width, channels). Floats are values (encoded in [0, 1] for
        PNG, TIFF and JPEG; linear for EXR), written from float32. Integers are code values:
        uint8 is divided by 255 and uint16 by 65535 (so 128 is 128/255, not white), for PNG,
        TIFF and JPEG only; other integer and bool dtypes raise ValueError, as does an integer
        array for EXR (code values are encoded: decode them to linear floats first).
    channels: names, default Y / Y,A / R,G,B / R,G,B,A by count.
    color_space, description: stored as attributes (irid:ColorSpace, ImageDescription).
        With ``tag`` true (the default) color_space is "" or one of irid's space names
        (:func:`color_spaces`; another raises KeyError), and the file also says so to other
        programs, which needs an RGB space (ValueError otherwise): PNG and TIFF get the space's
        ICC profile (:func:`icc_profile`), EXR its chromaticities (and adoptedNeutral when the
        white is not D65). With ``tag=False`` the text alone is written, whatever it is (an
        OpenColorIO name, or the "sRGB" OpenImageIO reports in read_image's metadata).
    icc_profile: bytes of a profile to embed instead (PNG, TIFF; checked as a file's would be).
    chromaticities: 8 values (red, green, blue, white x, y) to write instead (EXR).
        Either must describe the space color_space names, when both are given (ValueError).
    data_window, display_window: EXR's windows as read_image's metadata gives them, inclusive
        boxes (x min, y min, x max, y max): where the pixels sit (the box must be the array's
        width x height) and the frame they belong to. None: at 0, 0, the frame the image.
        EXR only (ValueError for other formats).
    compression: OpenImageIO's name for the format, or "" for its default. EXR: none, rle, zip,
        zips, piz, pxr24, b44, b44a, dwaa, dwab (zip, zips, dwaa and dwab take a level, "dwaa:45");
        TIFF: none, lzw, zip, packbits, jpeg (lossy); PNG: default, filtered, huffman, rle, fixed
        (zlib's strategies). Another name raises KeyError listing these.

    The file appears only when complete and never replaces what is not a regular file. Raises
    ValueError for a bad array or channel list, OSError when the file cannot be written.

    uint8 code values in a PNG tagged Display P3 (its ICC profile embedded), read back:

    >>> import os, tempfile, numpy as np, irid
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = os.path.join(folder, "one.png")
    ...     irid.write_image(path, np.array([[[255, 51, 0]]], dtype=np.uint8),
    ...                      color_space="display-p3")
    ...     pixels, metadata = irid.read_image(path)
    >>> print(np.round(pixels, 4))          # 51/255 = 0.2
    [[[1.  0.2 0. ]]]
    >>> metadata["integer"], irid.image_space(metadata)["space"]
    (True, 'display-p3')
    """
    if isinstance(bits, bool) or bits not in (8, 16):
        raise ValueError(f"bits: {bits!r}; valid values are 8 and 16")
    array = _code_values_scaled(array, _path(path))
    names = [_text(c, "channels") for c in (channels or [])]
    _check_compression(_text(compression, "compression"), _path(path))
    if icc_profile is not None and not isinstance(icc_profile, (bytes, bytearray)):
        raise ValueError("icc_profile: an ICC profile is bytes")
    if chromaticities is not None:
        chromaticities = _floats(chromaticities, "chromaticities")
    windows = [None if w is None else _box(w, name)
               for w, name in ((data_window, "data_window"), (display_window, "display_window"))]
    return _irid.write_image(_path(path), array, names, _text(color_space, "color_space"),
                             _text(description, "description"), int(bits),
                             _text(compression, "compression"), _flag(tag, "tag"),
                             None if icc_profile is None else bytes(icc_profile), chromaticities,
                             *windows)


def _box(value, name):
    """A window: 4 whole numbers."""
    if (isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 4 or
            any(isinstance(v, bool) or not isinstance(v, numbers.Integral) or abs(v) >= 2**62
                for v in value)):
        raise ValueError(f"{name}: {value!r} is not 4 whole numbers (x min, y min, x max, y max)")
    return [int(v) for v in value]


def _code_values_scaled(array, path):
    """uint8 and uint16 arrays as the values their codes stand for; other integers refused."""
    if isinstance(array, np.ma.MaskedArray):
        raise ValueError("array: a masked array (numpy.ma); irid would drop the mask: pass "
                         "array.filled(value) or array.data")
    a = np.asarray(array)
    if a.dtype.kind not in "uib":
        return array
    top = {1: 255.0, 2: 65535.0}.get(a.dtype.itemsize) if a.dtype.kind == "u" else None
    if top is None:
        raise ValueError(f"array: dtype {a.dtype}; integer arrays are code values, given as uint8 "
                         f"(0-255) or uint16 (0-65535), or pass floats (encoded values in [0, 1])")
    if os.path.splitext(path)[1].lower() == ".exr":
        raise ValueError(f"array: dtype {a.dtype} holds encoded code values, and EXR holds linear "
                         f"floats: decode them first, e.g. irid.convert(a / {top:g}, 'srgb', "
                         f"'srgb-linear')")
    return a.astype(np.float32) / np.float32(top)


# The compressions OpenImageIO 2.4 writes per format (its OpenEXR, TIFF and PNG plugins), and
# those that take ":LEVEL".
_COMPRESSIONS = {
    ".exr": ("none", "rle", "zip", "zips", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"),
    ".tif": ("none", "lzw", "zip", "packbits", "jpeg"),
    ".png": ("default", "filtered", "huffman", "rle", "fixed"),
}
_COMPRESSIONS[".tiff"] = _COMPRESSIONS[".tif"]
_COMPRESSIONS[".jpg"] = _COMPRESSIONS[".jpeg"] = ()    # "jpeg:QUALITY", 1 to 100
_LEVELLED = ("zip", "zips", "dwaa", "dwab")


def _check_compression(compression, path):
    if not compression:
        return
    ext = os.path.splitext(path)[1].lower()
    valid = _COMPRESSIONS.get(ext)
    if valid is None:
        return   # not a format irid writes: write_image names the formats it does
    name, _, level = compression.partition(":")
    if name in valid and not level:
        return
    if ext in (".jpg", ".jpeg"):
        if name == "jpeg" and level.isdigit() and 1 <= int(level) <= 100 and len(level) <= 3:
            return
        raise KeyError(f"compression {compression!r} is unknown for {ext} files; valid: "
                       f"jpeg:QUALITY with QUALITY 1 to 100 (default jpeg:95)")
    if ext == ".exr" and name in _LEVELLED and level.isdigit() and 0 < len(level) <= 4:
        return
    levelled = ", ".join(f"{n}:LEVEL" for n in _LEVELLED) if ext == ".exr" else ""
    raise KeyError(f"compression {compression!r} is unknown for {ext} files; valid: "
                   f"{', '.join(valid)}{', ' + levelled if levelled else ''}")



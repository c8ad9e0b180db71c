"""Gamut mapping: the clip methods on colours and images, their LUTs, OCIO configs and report."""

from __future__ import annotations

import functools
import numbers
import warnings

import numpy as np

from . import _irid
from ._args import _flag, _floats, _name, _names, _number, _path, _plain, _text, _white, _whole
from ._io import _file_facts

__all__ = [
    "Lut",
    "bake_lut",
    "clip",
    "clip_branches",
    "clip_image",
    "clip_methods",
    "clip_parameters",
    "clip_report",
    "simd_target",
    "write_ocio_config",
]

_RGB_SPACES = frozenset(_irid.rgb_color_space_names())


def clip_methods():
    """The names of the gamut-mapping methods, in the order of the reports.

    >>> import irid
    >>> irid.clip_methods()[:3]
    ['clamp', 'smits', 'smits-xyz']
    >>> "oklab-cusp" in irid.clip_methods()
    True
    """
    return _irid.clip_methods()


def clip_parameters(method):
    """The parameters of a method: a list of dicts (name, default, min, max, boolean,
    description). As keyword arguments of :func:`clip` a '-' in a name is written '_'.

    >>> import irid
    >>> [p["name"] for p in irid.clip_parameters("aces-rgc")][:3]
    ['limit-cyan', 'limit-magenta', 'limit-yellow']
    >>> irid.clip_parameters("smits")
    []
    """
    return _irid.clip_parameters(_name(method, "method"))


def simd_target():
    """The SIMD instruction set the float32 batch kernels run on here (AVX3, AVX2, ...).

    >>> import irid
    >>> isinstance(irid.simd_target(), str)      # which one depends on the processor
    True
    """
    return _irid.simd_target()


@functools.lru_cache(maxsize=64)
def _pipeline(method, source, target, peak, white, adaptation, params, inverse, display=False):
    return _irid.ClipPipeline(method, source, target, peak, white[0], white[1], adaptation,
                              list(params), inverse, display)


def _method_parameters(method, params):
    """The keyword arguments of a call as the method's parameters ("-" for "_"). A name the
    method does not take (a mistyped keyword, whatever its value) is an unknown name: KeyError
    naming it and what the method takes, before its value is looked at."""
    known = {p["name"] for p in _irid.clip_parameters(method)}
    values = {}
    for key, value in params.items():
        name = key.replace("_", "-")
        if name not in known:
            takes = ", ".join(sorted(n.replace("-", "_") for n in known)) or "none"
            raise KeyError(f"{key!r} is neither an argument nor a parameter of the method "
                           f"{method} (its parameters: {takes})")
        values[name] = _parameter_value(key, value)
    return values


def _parameter_value(name, value):
    if isinstance(value, (bool, np.bool_)):
        return 1.0 if value else 0.0
    if isinstance(value, numbers.Real):
        return float(value)
    raise ValueError(f"parameter {name}: {value!r} is not a number or a boolean")


def clip(rgb, method, source="srgb-linear", target=None, max=1.0, white="D65",
         adaptation="bradford", threads=0, inverse=False, out=None, **params):
    """Brings colours into an RGB space's gamut (what ``irid clip`` does to colours).

    rgb: array (..., 3) of triples of ``source``.
    method: one of :func:`clip_methods` ("smits", "oklab-cusp", "aces-rgc", ...).
    source: any space of :func:`convert`.
    target: the destination RGB space, whose linear cube [0, max]^3 is the gamut; the result is
        in it (encoded for an encoded name such as "srgb"). Default: ``source`` when it is an
        RGB space, else "srgb-linear".
    max: the gamut's peak (HDR), 0 < max <= 1e6.
    white, adaptation: as for :func:`convert`.
    threads: threads to use, 0 for all.
    inverse: apply the method's inverse (aces-rgc, smits-soft).
    out: a C-contiguous array of the result's dtype and shape to write into (may be ``rgb``
        itself, not a part of it).
    **params: the method's parameters (:func:`clip_parameters`), '-' written '_':
        ``clip(a, "aces-rgc", limit_cyan=1.2, clip=True)``.

    float64 runs the double methods: exactly what ``irid clip`` prints for CSV. float32 (any
    byte order) converts each colour to the target's linear RGB in double, rounds it to float
    and runs the SIMD batch kernels: smits and clamp give the bits of their float form, the
    others are within 1e-5 × max of the double methods on that float linear input (a method
    sensitive to its input, such as css across spaces, can differ more from the float64 path,
    which does not round in between). aces-rgc leaves colours beyond its limits slightly
    outside the cube unless ``clip=True``, as OpenColorIO does. Raises KeyError for unknown
    names, ValueError for bad values, shapes and non-numeric arrays.

    clamp cuts each channel to [0, max]; smits keeps the hue by moving towards the grey of the
    same luminance:

    >>> import numpy as np, irid
    >>> irid.clip([1.2, -0.1, 0.3], "clamp").tolist()
    [1.0, 0.0, 0.3]
    >>> np.round(irid.clip([[2.0, 0.5, 0.5], [0.2, 0.4, 0.6]], "smits"), 4).tolist()
    [[1.0, 0.7701, 0.7701], [0.2, 0.4, 0.6]]
    >>> irid.clip([2.0, 0.5, 0.5], "clamp", max=4.0).tolist()      # HDR: the cube [0, 4]^3
    [2.0, 0.5, 0.5]
    """
    # The pipelines already built, by their arguments as given: a repeated call skips the
    # checks (one dictionary lookup), which keeps the call on one colour near a microsecond.
    try:
        key = (method, source, target, max, white, adaptation, inverse, tuple(params.items()))
        p = _recent.get(key)
    except TypeError:   # an unhashable argument: the checks below refuse it
        key, p = None, None
    if p is None:
        p = _clip_pipeline(method, source, target, max, white, adaptation, inverse, params)
        if key is not None:
            if len(_recent) >= 256:
                _recent.clear()
            _recent[key] = p
    if threads.__class__ is not int or not 0 <= threads <= _irid.max_threads:
        threads = _whole(threads, "threads", 0, _irid.max_threads)
    return p.run(rgb, threads, out)


_recent = {}


def clip_branches(rgb, method, source="srgb-linear", target=None, max=1.0, white="D65",
                  adaptation="bradford", inverse=False, threads=0, **params):
    """Which branches of its definition the method takes for each colour, as uint64 numbers.

    Arguments as for :func:`clip`; the colours are taken in float64. Two colours with the same
    number go through the same branches, and the method's output is continuous between them;
    where the number changes, the definition itself may jump (css's binary search, css-raytrace's
    passes, the pieces of the Oklab methods' lines, oklab-cusp's cusp, luv-hue's local minima
    and CIELUV's undefined chromaticity; docs/GAMUT.md, "Where a method may jump"). 0 for
    colours inside the gamut and for the methods without such branches.

    Returns uint64 of the input's shape without its last axis.

    >>> import irid
    >>> b = irid.clip_branches([[0.5, 0.5, 0.5], [1.5, 0.2, 0.1]], "oklab-cusp")
    >>> b.dtype, int(b[0]), bool(b[1] != 0)
    (dtype('uint64'), 0, True)
    """
    p = _clip_pipeline(method, source, target, max, white, adaptation, inverse, params)
    threads = _whole(threads, "threads", 0, _irid.max_threads)
    return p.branches(np.asarray(rgb, dtype=np.float64), threads)


def _clip_pipeline(method, source, target, max, white, adaptation, inverse, params,
                   image=False):
    _name(method, "method")
    _name(source, "source")
    if target is None:
        target = source if _irid.canonical_space_name(source) in _RGB_SPACES else "srgb-linear"
    _name(target, "target")
    peak = _number(max, "max")
    values = _method_parameters(method, params)
    # image: a file holds what a display shows (display_clip_settings in irid/gamut/clip.h).
    return _pipeline(method, source, target, peak, _white(white),
                     _name(adaptation, "adaptation"), tuple(sorted(values.items())),
                     _flag(inverse, "inverse"), image)


Lut = _irid.Lut


def bake_lut(method, source="srgb-linear", target="srgb", size=33, shaper="none", domain=None,
             stops=14, max=1.0, white="D65", adaptation="bradford", threads=0, inverse=False,
             **params):
    """Bakes a clip method as a 3D LUT (what ``irid lut`` writes): a :class:`Lut`.

    method, source, target, max, white, adaptation, inverse, **params: as for :func:`clip`;
    the output is ``target``'s, encoded for an encoded name ("srgb").
    size: nodes per axis, 2 to 129 (17, 33, 65 usual).
    shaper: "none" or "log2" (for linear and HDR sources; only a .clf file can carry it).
    domain: (lo, hi) covered on every axis, default (0, max). stops: the log2 shaper's span.
    threads: threads to use, 0 for all.

    ``lut.write(path)`` writes .cube (Resolve/Adobe; ffmpeg, OCIO), .clf (Academy/ASC CLF;
    OCIO) or .spi3d (Sony; OCIO) by the extension, whole or not at all (OSError when it cannot;
    ValueError when the format cannot carry the domain: .spi3d is [0, 1] only, .cube has no
    shaper; KeyError for another extension). ``lut.text(format)`` is the file's text.
    ``lut.apply(rgb, interpolation="trilinear")`` evaluates the LUT on (..., 3) colours as a
    client does ("trilinear" or "tetrahedral"; OCIO uses trilinear for .cube and .spi3d, the
    .clf asks for tetrahedral); it returns float64.
    Raises KeyError for unknown names and ValueError for bad values.

    >>> import irid
    >>> lut = irid.bake_lut("clamp", size=2)        # srgb-linear to encoded srgb
    >>> lut.size, lut.table.shape
    (2, (2, 2, 2, 3))
    >>> lut.apply([[0.0, 1.0, 0.0]]).tolist()
    [[0.0, 1.0, 0.0]]
    >>> print(lut.text("cube").splitlines()[2])
    LUT_3D_SIZE 2
    """
    if target is None:
        target = "srgb"
    p = _clip_pipeline(method, source, target, max, white, adaptation, inverse, params)
    if domain is None:
        lo, hi = 0.0, float(max)
    else:
        try:
            lo, hi = (float(v) for v in domain)
        except (TypeError, ValueError):
            raise ValueError(f"domain: {domain!r}; expected (lo, hi)") from None
    return _irid.bake_lut(p, _whole(size, "size", 2, 129), _name(shaper, "shaper"), lo, hi,
                          _whole(stops, "stops", 1, 40), _whole(threads, "threads", 0, _irid.max_threads))


def write_ocio_config(dir, source="acescg-linear", display="srgb", methods=None, size=33,
                      adaptation="bradford", threads=0, range=None, aces2=None):
    """Writes an OpenColorIO 2 config offering the clip methods as looks (``irid ocio-config``).

    dir: the folder (created if missing): config.ocio and luts/irid-METHOD.clf, written as a set
        (a failure leaves the old config whole); LUTs of an earlier config under irid's names
        that this one does not write are removed, other files stay.
    source: the scene's RGB space; its linear form is the config's reference (and scene_linear
        role), an encoded source a colour space decoded from it. display: the display's RGB
        space, whose cube is the gamut (it may be the source's own): one matrix from the
        reference and its transfer function as an OCIO transform.
    methods: the methods offered (default: all of :func:`clip_methods`, each once), each a look
        "irid-METHOD" in the display's linear space and a view METHOD on the display
        "DISPLAY display", beside a view "unclipped".
    size: the LUTs' nodes per axis, 5 to 129; 0 and 1 are nodes on every axis, so colours inside
        the gamut go through a hard method's look unchanged.
    range: (lo, hi), the source values the looks cover (default (-1, 16) for a linear source,
        (0, 1) for an encoded one); beyond them inputs clamp.

    aces2: the ACES 2.0 displays (:func:`display_names`) the display offers as views "ACES 2.0
        NAME", each baked in luts/aces2-NAME.clf; None (``irid ocio-config --aces2 auto``):
        every one whose default encoding is ``display``; [] (``--aces2 none``): none.

    Returns the path of config.ocio. Raises KeyError for unknown names, ValueError for bad
    values (a space that is not RGB, a method named twice, a bad range), OSError when a file
    cannot be written.

    >>> import os, tempfile, irid
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = irid.write_ocio_config(folder, methods=["clamp", "smits"], size=5)
    ...     os.path.basename(path), sorted(os.listdir(os.path.join(folder, "luts")))
    ('config.ocio', ['aces2-sdr-100nit-rec709-d60-in-rec709-d65.clf', 'aces2-sdr-100nit-rec709.clf', 'irid-clamp.clf', 'irid-smits.clf'])
    """
    names = list(_names(methods, "methods")) if methods is not None else []
    aces2 = list(_names(aces2, "aces2")) if aces2 is not None else None
    if range is not None:
        range = tuple(_floats(range, "range"))
        if len(range) != 2:
            raise ValueError(f"range: {range!r}; give (lo, hi)")
    return _irid.write_ocio_config(_path(dir), _name(source, "source"), _name(display, "display"),
                                   names, _whole(size, "size", 5, 129),
                                   _name(adaptation, "adaptation"),
                                   _whole(threads, "threads", 0, _irid.max_threads), range, aces2)


def clip_image(pixels, channels, method, source=None, target=None, premultiplied=False,
               premultiplied_out=None, encode=False, max=1.0, white="D65", adaptation="bradford",
               threads=0, inverse=False, **params):
    """Clips an image's colours as ``irid clip IN OUT`` does; returns (pixels, channels).

    pixels: (height, width, channels), as :func:`read_image` returns them.
    channels: their names. The colour is R, G and B by name, else X, Y and Z (a CIE XYZ image,
        whose channels come back named R, G, B); every other channel, alpha ("A") included, is
        returned as it was.
    source: the colour's space; default "srgb-linear", or "xyz" for X, Y, Z channels (which
        allow no other). Or the metadata :func:`read_image` returned: the space the file says it
        holds (:func:`image_space`), as ``irid clip IN OUT`` takes it without ``--from``; a
        damaged or unusable profile, or CMYK samples without one, raise ValueError. What
        ``irid clip`` notes on stderr (an untagged integer file taken as sRGB, encoded values
        taken as linear light) is a UserWarning here.
    premultiplied: the colour is premultiplied by A (an EXR's, the OpenEXR convention): it is
        clipped unpremultiplied (a pixel of alpha 0 keeps its values).
    premultiplied_out: premultiply the result by A again (default: as ``premultiplied``; False
        for a PNG or TIFF file, whose colour is not premultiplied).
    encode: apply the target's transfer function (for a PNG or TIFF file).
    The other arguments are :func:`clip`'s; aces-rgc gets ``clip=True`` unless given, as images
    do on the command line. The result is a new float32 array.

    A 1 × 2 image with alpha, whose A channel comes back as it was:

    >>> import numpy as np, irid
    >>> pixels = np.array([[[1.5, 0.2, 0.1, 0.5], [0.2, 0.4, 0.6, 1.0]]], dtype=np.float32)
    >>> clipped, channels = irid.clip_image(pixels, ["R", "G", "B", "A"], "clamp")
    >>> channels, clipped.dtype
    (['R', 'G', 'B', 'A'], dtype('float32'))
    >>> print(clipped)
    [[[1.  0.2 0.1 0.5]
      [0.2 0.4 0.6 1. ]]]
    """
    names = [_text(c, "channels") for c in channels]
    xyz_channels = _irid.image_colour_channels(names)[3]
    # Where the colours come from is the library's decision (irid/exchange/image_source.h), as
    # for irid clip IN OUT; what irid clip notes on stderr is a warning here.
    if isinstance(source, dict):
        decided = _irid.ImageSource(_file_facts(source), xyz_channels, None)
        given = None
    else:
        given = None if source is None else _name(source, "source")
        decided = _irid.ImageSource({}, xyz_channels, given)
    for note in decided.notes:
        warnings.warn(note, stacklevel=2)
    if target is None:
        target = given if given is not None and _irid.canonical_space_name(given) in _RGB_SPACES else "srgb-linear"
    _name(target, "target")
    peak = _number(max, "max")
    wx, wy = _white(white)
    p = _irid.ClipPipeline(_name(method, "method"), decided, target, peak, wx, wy,
                           _name(adaptation, "adaptation"),
                           sorted(_method_parameters(method, params).items()),
                           _flag(inverse, "inverse"), True)
    _plain(pixels=pixels)
    out = np.array(pixels, dtype=np.float32, order="C", copy=True)
    if out.ndim != 3:
        raise ValueError(f"pixels: shape {out.shape}; expected (height, width, channels)")
    pre_in = _flag(premultiplied, "premultiplied")
    pre_out = pre_in if premultiplied_out is None else _flag(premultiplied_out, "premultiplied_out")
    names = _irid.clip_image(out, names, p, pre_in, pre_out, _flag(encode, "encode"),
                             _whole(threads, "threads", 0, _irid.max_threads), decided)
    return out, names


def clip_report(set="all", target="srgb", min_seconds=0.2):
    """Every clip method measured on a set of colours (what ``irid clip-report`` prints, as data).

    set: "spectrum", "interference", "rec2020", "ramps" or "all" (each set, then their union).
    target: the destination RGB space (its linear cube is the gamut).
    min_seconds: how long each method's timing runs (0: one pass).

    Returns a list with one dict per set: "set", "description", "destination", "max", "size",
    "out_of_gamut", "ramps", "input_banding" and "methods", a dict by method name of its
    measures: "delta_e2000", "hue_lab", "hue_oklab", "hue_luv", "delta_y", "in_gamut_moved",
    "banding", "collapse", "collapse_relative" (each {"mean", "p95", "max", "count"}),
    "hue_undefined", "chroma_kept", "chroma_kept_count" and "colors_per_second". The
    definitions are in docs/GAMUT.md. aces-rgc is measured with clip=True.

    >>> import irid
    >>> report = irid.clip_report("spectrum", min_seconds=0)
    >>> [r["set"] for r in report], list(report[0]["methods"]) == irid.clip_methods()
    (['spectrum'], True)
    >>> report[0]["methods"]["clamp"]["delta_e2000"].keys()
    dict_keys(['mean', 'p95', 'max', 'count'])
    """
    seconds = _number(min_seconds, "min_seconds")  # checked first, as before the split
    return _irid.clip_report(_name(set, "set"), _name(target, "target"), seconds)

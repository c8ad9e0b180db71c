"""irid: interference colours and gamut mapping, on numpy arrays.

The library behind the ``irid`` command (C++20), for Python:

* colour: :func:`convert` between every space of ``irid convert``, :func:`delta_e`, the CIE
  observers (:func:`cmfs`) and illuminants (:func:`illuminant`, :func:`blackbody`),
  :func:`spectrum_to_xyz` for many spectra at once, and the thesis' primaries transform
  (:func:`primaries_transform`, Smits 1990, Figure 2);
* gamut mapping: :func:`clip` and :func:`clip_image` with every method and parameter of
  ``irid clip``
  (:func:`clip_methods`, :func:`clip_parameters`) and :func:`clip_report`;
* optics: :class:`Material` (by name, constant, Cauchy, Sellmeier, CSV), :class:`Film` (the
  exact optics, the thesis' single film, multilayer and Morpho wing) with its spectra and
  colours over arrays of thicknesses and angles, :func:`film_reflectance`, :func:`film_color`,
  the thesis' closed forms (eq. 19–29: :func:`thesis_film_reflectance`,
  :func:`thesis_multilayer_reflectance`, :func:`morpho_reflectance`, ...) and colour tables
  (:meth:`Film.color_table`, :func:`thesis_film_table`); the renderers' thin-film colour models
  (glTF, Belcour & Barla, Cycles: :func:`renderer_film_color`, :func:`renderer_film_models`);
* images: :func:`read_image` and :func:`write_image` through OpenImageIO;
* rendering: :func:`render` of the thesis' scenes (:func:`scenes`), a scene file or a dict.

Arrays in, arrays out: a colour argument is any array of shape (..., 3), float32 or float64
(anything else is taken as float64), and the result has the same shape. A float32 C-contiguous
array is read without a copy and gives float32; ``out=`` writes the result into an existing
array (it may be the input itself). Long calls release the GIL.

Errors: ``ValueError`` for bad values (with the library's message), ``KeyError`` for unknown
names (listing the valid ones), ``OSError`` for files.

Example::

    import numpy as np, irid
    rgb = np.array([[1.2, -0.1, 0.3], [0.5, 0.5, 0.5]], dtype=np.float32)
    irid.clip(rgb, "oklab-cusp", out=rgb)        # in place, sRGB linear
    lab = irid.convert(rgb, "srgb-linear", "oklab")
"""

from __future__ import annotations

import functools
import numbers
import warnings
import os

import numpy as np

from . import _irid
from ._optics import (Film, FilmColors, FilmColorTable, FilmColorTable2D, Material,
                      ThesisFilmTable, film_color, film_reflectance, materials,
                      renderer_film_color, renderer_film_models,
                      morpho_effective_thickness, morpho_reflectance, thesis_effective_thickness,
                      thesis_film_angle, thesis_film_reflectance, thesis_film_table,
                      thesis_matched_k, thesis_multilayer_effective_thickness,
                      thesis_multilayer_reflectance, thesis_phase_change, thesis_unit_peak_k)
from ._render import Render, gallery, render, scenes

__all__ = [
    "Film",
    "FilmColorTable",
    "FilmColorTable2D",
    "FilmColors",
    "Lut",
    "Material",
    "Render",
    "ThesisFilmTable",
    "bake_lut",
    "blackbody",
    "clip",
    "clip_branches",
    "clip_image",
    "clip_methods",
    "clip_parameters",
    "clip_report",
    "cmfs",
    "color_spaces",
    "convert",
    "delta_e",
    "film_color",
    "film_reflectance",
    "gallery",
    "icc_profile",
    "illuminant",
    "image_space",
    "materials",
    "morpho_effective_thickness",
    "morpho_reflectance",
    "primaries_transform",
    "read_icc_profile",
    "read_image",
    "render",
    "renderer_film_color",
    "renderer_film_models",
    "rgb_color_spaces",
    "scenes",
    "simd_target",
    "spectrum_to_xyz",
    "thesis_effective_thickness",
    "thesis_film_angle",
    "thesis_film_reflectance",
    "thesis_film_table",
    "thesis_matched_k",
    "thesis_multilayer_effective_thickness",
    "thesis_multilayer_reflectance",
    "thesis_phase_change",
    "thesis_unit_peak_k",
    "white_point",
    "write_image",
    "write_ocio_config",
]


__version__ = "0.1.0"

_RGB_SPACES = frozenset(_irid.rgb_color_space_names())


def _name(value, what):
    """A name argument: a str (KeyError from the library when it is unknown)."""
    if not isinstance(value, str):
        raise ValueError(f"{what}: {value!r} is not a name (str)")
    return value


def _text(value, what):
    """A text argument stored in a file: a str without NUL bytes."""
    if not isinstance(value, str):
        raise ValueError(f"{what}: {value!r} is not a str")
    if "\0" in value:
        raise ValueError(f"{what}: contains a NUL byte")
    return value


def _path(path):
    """A file name: str, bytes or os.PathLike, without NUL bytes."""
    try:
        p = os.fsdecode(os.fspath(path))
    except TypeError:
        raise ValueError(f"path: {path!r} is not a file name") from None
    if "\0" in p:
        raise ValueError(f"path: {p!r} contains a NUL byte")
    return p


def _whole(value, what, lo, hi):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ValueError(f"{what}: {value!r} is not a whole number")
    if not lo <= value <= hi:
        raise ValueError(f"{what}: {value} must be in [{lo}, {hi}]")
    return int(value)


def _flag(value, what):
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{what}: {value!r} is not True or False")
    return bool(value)


@functools.lru_cache(maxsize=32)
def _named_white(name):
    return _irid.white_point(name)


def _white(white):
    """A reference white given by name ('D65', ...) or as chromaticity (x, y) → (x, y)."""
    if isinstance(white, str):
        return _named_white(white)
    try:
        x, y = (float(v) for v in white)
    except (TypeError, ValueError):
        raise ValueError(
            f"white: {white!r} is neither a white point's name nor a chromaticity (x, y)"
        ) from None
    _irid.check_white(x, y)   # ValueError unless inside the chromaticity diagram
    return x, y


def color_spaces():
    """Every space name of :func:`convert`: xyz, xyy, luv, lab, lchuv, lchab, oklab, oklch,
    then NAME (encoded) and NAME-linear of each built-in RGB space."""
    return _irid.color_space_names()


def rgb_color_spaces():
    """The RGB space names only (the gamuts :func:`clip` can map into)."""
    return _irid.rgb_color_space_names()


def white_point(name):
    """The chromaticity (x, y) of a named white: D65, D50, D55, D75, A, C, E, or "x,y"."""
    return _irid.white_point(name)


def convert(a, source, target, white="D65", adaptation="bradford", out=None):
    """Converts colours from one space to another (what ``irid convert`` does).

    a: array (..., 3) of triples of ``source``; float32 stays float32, anything else is float64.
    source, target: names from :func:`color_spaces` ("srgb", "srgb-linear", "xyz", "lab",
        "oklab", "acescg", ...). XYZ has Y = 1 for the reference white.
    white: the reference white of XYZ, CIELUV and CIELAB, a name ("D65") or (x, y).
    adaptation: where a space's own white differs from the reference white: "bradford",
        "cat02", "von-kries" or "none".
    out: a C-contiguous array of the result's dtype and shape to write into (may be ``a``
        itself, not a part of it).

    Returns the converted array, of the same shape. Converting a space to itself returns the
    colours bit for bit; between two forms of one space (srgb and srgb-linear) only the
    transfer function is applied (no trip through XYZ). Raises KeyError for an unknown space or
    white, ValueError for a bad shape, a non-numeric array or an xyY colour with y = 0 and
    Y != 0.
    """
    wx, wy = _white(white)
    return _irid.convert(a, _name(source, "source"), _name(target, "target"), wx, wy,
                         _name(adaptation, "adaptation"), out)


def delta_e(a, b, metric="ciede2000"):
    """Colour differences of pairs: ``a`` and ``b`` broadcast against each other, shape (..., 3)
    (each a triple or an array of triples; a scalar raises ValueError).

    metric: "ciede2000" (CIE 142:2001) or "cie76" on CIELAB, "cieuv" (ΔE*uv) on CIELUV,
        "oklab" (ΔEOK) on Oklab.

    Returns float64 of the broadcast shape without its last axis.
    """
    for name, v in (("a", a), ("b", b)):
        if isinstance(v, np.ma.MaskedArray):
            raise ValueError(f"{name}: a masked array (numpy.ma); irid has no masked operations "
                             f"and would drop the mask: pass {name}.filled(value) or {name}.data")
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    for name, v in (("a", a), ("b", b)):
        # A colour is a triple: a scalar broadcast into (v, v, v) would be a guess.
        if v.ndim == 0 or v.shape[-1] != 3:
            raise ValueError(f"{name}: shape {v.shape}; colours are (..., 3) triples")
    try:
        a, b = np.broadcast_arrays(a, b)
    except ValueError:
        raise ValueError(f"a and b: shapes {a.shape} and {b.shape} do not broadcast") from None
    return _irid.delta_e(a, b, _name(metric, "metric"))


def cmfs(observer="cie1931"):
    """A CIE standard observer's colour-matching functions (CIE 015:2018), 360-830 nm at 1 nm.

    observer: "cie1931" (2°) or "cie1964" (10°).
    Returns (wavelengths (471,), values (471, 3) as x̄, ȳ, z̄).
    """
    return _irid.cmfs(_name(observer, "observer"))


def illuminant(name="D65", cct=None):
    """An illuminant's relative spectral power, 360-830 nm at 1 nm (100 at 560 nm for D and A).

    name: "D65", "D50", "D55", "D75", "A", "E", "D<CCT>" ("D9300"), "blackbody:<T>"; or "D"
        with ``cct`` (4000-25000 K) for the CIE daylight of that correlated colour temperature.
    Returns (wavelengths (471,), values (471,)).
    """
    _name(name, "illuminant")
    if cct is not None:
        if name.upper() != "D":
            raise ValueError(f"illuminant: cct is for the daylight series, name 'D', not {name!r}")
        if not isinstance(cct, numbers.Real):
            raise ValueError(f"illuminant: cct {cct!r} is not a number")
        return _irid.daylight(float(cct))
    return _irid.illuminant(name)


def blackbody(t):
    """Planck's law at temperature ``t`` (100 to 1e6 K), 360-830 nm at 1 nm, normalised to 100
    at 560 nm. Returns (wavelengths (471,), values (471,))."""
    if not isinstance(t, numbers.Real):
        raise ValueError(f"blackbody: temperature {t!r} is not a number")
    return _irid.blackbody(float(t))


def spectrum_to_xyz(wavelengths, values, illuminant="D65", observer="cie1931"):
    """XYZ of reflectance spectra under an illuminant, white Y = 1 (what ``irid xyz`` does).

    wavelengths: (n,) strictly increasing, in nm, any spacing (resampled to 1 nm, ends held,
        CIE 015:2018 §7.2.2); must overlap 360-830 nm.
    values: (..., n), one spectrum per row.
    illuminant: "D65", "D50", "D55", "D75", "A", "E", "D<CCT>" ("D5000") or "blackbody:<T>".
    observer: "cie1931" or "cie1964".
    Returns float64 (..., 3).
    """
    return _irid.spectrum_to_xyz(wavelengths, values, _name(illuminant, "illuminant"),
                                 _name(observer, "observer"))


def primaries_transform(red=645.0, green=526.0, blue=444.0, observer="cie1931"):
    """The thesis' Figure 2: colour-matching functions of three monochromatic primaries.

    Returns (wavelengths (471,), rgb (471, 3), xyz_to_rgb (3, 3)) with
    rgb(λ) = xyz_to_rgb · (x̄, ȳ, z̄)(λ).
    """
    return _irid.primary_matching_functions(float(red), float(green), float(blue),
                                            _name(observer, "observer"))


def clip_methods():
    """The names of the gamut-mapping methods, in the order of the reports."""
    return _irid.clip_methods()


def clip_parameters(method):
    """The parameters of a method: a list of dicts (name, default, min, max, boolean,
    description). As keyword arguments of :func:`clip` a '-' in a name is written '_'."""
    return _irid.clip_parameters(_name(method, "method"))


def simd_target():
    """The SIMD instruction set the float32 batch kernels run on here (AVX3, AVX2, ...)."""
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
    if threads.__class__ is not int or not 0 <= threads <= 1 << 20:
        threads = _whole(threads, "threads", 0, 1 << 20)
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
    """
    p = _clip_pipeline(method, source, target, max, white, adaptation, inverse, params)
    threads = _whole(threads, "threads", 0, 1 << 20)
    return p.branches(np.asarray(rgb, dtype=np.float64), threads)


def _clip_pipeline(method, source, target, max, white, adaptation, inverse, params,
                   image=False):
    _name(method, "method")
    _name(source, "source")
    if target is None:
        target = source if source in _RGB_SPACES else "srgb-linear"
    _name(target, "target")
    if not isinstance(max, numbers.Real) or isinstance(max, bool):
        raise ValueError(f"max: {max!r} is not a number")
    values = _method_parameters(method, params)
    # image: a file holds what a display shows (display_clip_settings in irid/gamut/clip.h).
    return _pipeline(method, source, target, float(max), _white(white),
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
                          _whole(stops, "stops", 1, 40), _whole(threads, "threads", 0, 1 << 20))


def write_ocio_config(dir, source="acescg-linear", display="srgb", methods=None, size=33,
                      adaptation="bradford", threads=0, range=None):
    """Writes an OpenColorIO 2 config offering the clip methods as looks (``irid ocio-config``).

    dir: the folder (created if missing): config.ocio and luts/irid-METHOD.clf.
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

    Returns the path of config.ocio. Raises KeyError for unknown names, ValueError for bad
    values (a space that is not RGB, a method named twice, a bad range), OSError when a file
    cannot be written.
    """
    names = list(_names(methods, "methods")) if methods is not None else []
    if range is not None:
        range = tuple(_floats(range, "range"))
        if len(range) != 2:
            raise ValueError(f"range: {range!r}; give (lo, hi)")
    return _irid.write_ocio_config(_path(dir), _name(source, "source"), _name(display, "display"),
                                   names, _whole(size, "size", 5, 129),
                                   _name(adaptation, "adaptation"),
                                   _whole(threads, "threads", 0, 1 << 20), range)


def _names(values, what):
    if isinstance(values, str):
        raise ValueError(f"{what}: give a list of names, not one string")
    return [_name(v, what) for v in values]


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
        target = given if given in _RGB_SPACES else "srgb-linear"
    _name(target, "target")
    if not isinstance(max, numbers.Real) or isinstance(max, bool):
        raise ValueError(f"max: {max!r} is not a number")
    wx, wy = _white(white)
    p = _irid.ClipPipeline(_name(method, "method"), decided, target, float(max), wx, wy,
                           _name(adaptation, "adaptation"),
                           sorted(_method_parameters(method, params).items()),
                           _flag(inverse, "inverse"), True)
    if isinstance(pixels, np.ma.MaskedArray):
        raise ValueError("pixels: a masked array (numpy.ma); irid has no masked operations and "
                         "would drop the mask: pass pixels.filled(value) or pixels.data")
    out = np.array(pixels, dtype=np.float32, order="C", copy=True)
    if out.ndim != 3:
        raise ValueError(f"pixels: shape {out.shape}; expected (height, width, channels)")
    pre_in = _flag(premultiplied, "premultiplied")
    pre_out = pre_in if premultiplied_out is None else _flag(premultiplied_out, "premultiplied_out")
    names = _irid.clip_image(out, names, p, pre_in, pre_out, _flag(encode, "encode"),
                             _whole(threads, "threads", 0, 1 << 20), decided)
    return out, names


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
    }


def _floats(values, what):
    try:
        return [float(v) for v in values]
    except (TypeError, ValueError):
        raise ValueError(f"{what}: {values!r} is not a sequence of numbers") from None


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
    """
    f = _irid.FileSpace(_file_facts(metadata))
    return {"space": f.space, "origin": f.origin, "assumed": f.assumed, "encoded": f.encoded,
            "exact": f.exact}


def icc_profile(space, description=""):
    """The ICC profile (version 4.3, display class, matrix/TRC, built by Little CMS) of one of
    irid's RGB spaces ("display-p3", "rec2020", ...), as bytes: what irid embeds in the PNG and
    TIFF files it writes. description: the profile's description ("" for "NAME (irid)")."""
    return _irid.icc_profile(_name(space, "space"), _text(description, "description"))


def read_icc_profile(data):
    """What an ICC profile says, as irid reads it (irid/exchange/icc.h): a dict with
    "description", "version", "exact" (a matrix/TRC profile with one curve, taken exactly),
    "reason" (why not, otherwise), "space" (the built-in space it is, or None), "primaries"
    ((x, y) of red, green, blue), "white" (x, y) and "transfer" ({"kind": "parametric",
    "parameters": (g, a, b, c, d, e, f)} in ICC.1's type-4 form, or {"kind": "sampled",
    "samples": (...)}); the last four None for a profile that is not exact. Raises ValueError
    for a profile irid cannot use, with the reason."""
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
    the file had one that is damaged, and "icc_profile_damage" says how, else None), "chromaticities" (an EXR's 8 values, or None) and
    "adopted_neutral" (an EXR's x, y, or None). :func:`image_space` says what space they name.
    Raises OSError for a file that cannot be read whole (missing, not an image, truncated or
    corrupt pixel data, a header declaring more than the file holds, larger than 64 Mpixel).
    """
    return _irid.read_image(_path(path))


def write_image(path, array, channels=None, color_space="", description="", bits=8,
                compression="", tag=True, icc_profile=None, chromaticities=None):
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
    compression: OpenImageIO's name for the format, or "" for its default. EXR: none, rle, zip,
        zips, piz, pxr24, b44, b44a, dwaa, dwab (zip, zips, dwaa and dwab take a level, "dwaa:45");
        TIFF: none, lzw, zip, packbits, jpeg (lossy); PNG: default, filtered, huffman, rle, fixed
        (zlib's strategies). Another name raises KeyError listing these.

    The file appears only when complete and never replaces what is not a regular file. Raises
    ValueError for a bad array or channel list, OSError when the file cannot be written.
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
    return _irid.write_image(_path(path), array, names, _text(color_space, "color_space"),
                             _text(description, "description"), int(bits),
                             _text(compression, "compression"), _flag(tag, "tag"),
                             None if icc_profile is None else bytes(icc_profile), chromaticities)


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
    """
    if not isinstance(min_seconds, numbers.Real) or isinstance(min_seconds, bool):
        raise ValueError(f"min_seconds: {min_seconds!r} is not a number")
    return _irid.clip_report(_name(set, "set"), _name(target, "target"), float(min_seconds))

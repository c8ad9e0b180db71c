"""Colour: spaces and conversions, colour differences, CIE observers, illuminants and spectra."""

from __future__ import annotations

import numbers

import numpy as np

from . import _irid
from ._args import _name, _plain, _white

__all__ = [
    "blackbody",
    "cmfs",
    "color_spaces",
    "convert",
    "delta_e",
    "illuminant",
    "primaries_transform",
    "rgb_color_spaces",
    "spectrum_to_xyz",
    "white_point",
]


def color_spaces():
    """Every space name of :func:`convert`: xyz, xyy, luv, lab, lchuv, lchab, oklab, oklch,
    then NAME (encoded) and NAME-linear of each built-in RGB space.

    >>> import irid
    >>> irid.color_spaces()[:10]
    ['xyz', 'xyy', 'luv', 'lab', 'lchuv', 'lchab', 'oklab', 'oklch', 'srgb', 'srgb-linear']
    """
    return _irid.color_space_names()


def rgb_color_spaces():
    """The RGB space names only (the gamuts :func:`clip` can map into).

    >>> import irid
    >>> irid.rgb_color_spaces()[:4]
    ['srgb', 'srgb-linear', 'display-p3', 'display-p3-linear']
    >>> "lab" in irid.rgb_color_spaces()
    False
    """
    return _irid.rgb_color_space_names()


def white_point(name):
    """The chromaticity (x, y) of a named white: D65, D50, D55, D75, A, C, E, or "x,y".

    >>> import irid
    >>> irid.white_point("D65")
    (0.3127, 0.329)
    >>> irid.white_point("E")
    (0.3333333333333333, 0.3333333333333333)
    """
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

    sRGB's white is D65's, X = x/y and Z = (1 - x - y)/y; 18 % grey is L* = 116 · 0.18^⅓ - 16:

    >>> import numpy as np, irid
    >>> np.round(irid.convert([1.0, 1.0, 1.0], "srgb-linear", "xyz"), 4).tolist()
    [0.9505, 1.0, 1.0891]
    >>> np.round(irid.convert([[0.18, 0.18, 0.18]], "srgb-linear", "lab"), 3).tolist()
    [[49.496, 0.0, 0.0]]
    >>> a = np.array([0.5, 0.5, 0.5], dtype=np.float32)
    >>> irid.convert(a, "srgb-linear", "srgb", out=a) is a    # in place, float32
    True
    >>> print(np.round(a, 4))
    [0.7354 0.7354 0.7354]
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

    >>> import irid
    >>> float(irid.delta_e([50.0, 10.0, -5.0], [50.0, 10.0, -5.0]))
    0.0
    >>> irid.delta_e([[50, 0, 0], [50, 3, 4]], [50, 0, 0], "cie76").tolist()   # Euclidean
    [0.0, 5.0]
    """
    _plain(a=a, b=b)
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

    >>> import irid
    >>> wavelengths, xyz = irid.cmfs()
    >>> wavelengths[0], wavelengths[-1], xyz.shape
    (360.0, 830.0, (471, 3))
    >>> float(xyz[wavelengths == 555, 1][0])      # ȳ peaks at 555 nm
    1.0
    """
    return _irid.cmfs(_name(observer, "observer"))


def illuminant(name="D65", cct=None):
    """An illuminant's relative spectral power, 360-830 nm at 1 nm (100 at 560 nm for D and A).

    name: "D65", "D50", "D55", "D75", "A", "E", "D<CCT>" ("D9300"), "blackbody:<T>"; or "D"
        with ``cct`` (4000-25000 K) for the CIE daylight of that correlated colour temperature.
    Returns (wavelengths (471,), values (471,)).

    >>> import irid
    >>> wavelengths, power = irid.illuminant("D50")
    >>> power.shape, float(power[wavelengths == 560][0])
    ((471,), 100.0)
    >>> wavelengths, power = irid.illuminant("D", cct=6000)
    >>> float(power[wavelengths == 560][0])
    100.0
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
    at 560 nm. Returns (wavelengths (471,), values (471,)).

    A blackbody at 5000 K emits more at 830 nm than at 360 nm:

    >>> import irid
    >>> wavelengths, power = irid.blackbody(5000)
    >>> float(power[wavelengths == 560][0]), bool(power[-1] > power[0])
    (100.0, True)
    """
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

    The perfect white reflector is the illuminant's white, and half of it half as bright:

    >>> import numpy as np, irid
    >>> xyz = irid.spectrum_to_xyz([360, 830], [[1.0, 1.0], [0.5, 0.5]])
    >>> np.round(xyz, 4).tolist()
    [[0.9505, 1.0, 1.0888], [0.4752, 0.5, 0.5444]]
    """
    return _irid.spectrum_to_xyz(wavelengths, values, _name(illuminant, "illuminant"),
                                 _name(observer, "observer"))


def primaries_transform(red=645.0, green=526.0, blue=444.0, observer="cie1931"):
    """The thesis' Figure 2: colour-matching functions of three monochromatic primaries.

    Returns (wavelengths (471,), rgb (471, 3), xyz_to_rgb (3, 3)) with
    rgb(λ) = xyz_to_rgb · (x̄, ȳ, z̄)(λ).

    >>> import numpy as np, irid
    >>> wavelengths, rgb, xyz_to_rgb = irid.primaries_transform()
    >>> rgb.shape, xyz_to_rgb.shape
    ((471, 3), (3, 3))
    >>> bool(np.allclose(rgb, irid.cmfs()[1] @ xyz_to_rgb.T))
    True
    """
    return _irid.primary_matching_functions(float(red), float(green), float(blue),
                                            _name(observer, "observer"))

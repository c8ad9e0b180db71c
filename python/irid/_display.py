"""Display rendering: scene colours through the ACES 2.0 Output Transform to a display, and back."""

from __future__ import annotations

from . import _irid
from ._args import _flag, _name, _number, _whole

__all__ = ["bake_display_lut", "display_has_scene_value", "display_names", "display_transform"]


def display_names():
    """The displays of :func:`display_transform` (OpenColorIO's 31 built-in ACES 2.0 displays).

    >>> import irid
    >>> len(irid.display_names()), irid.display_names()[0]
    (31, 'sdr-100nit-rec709')
    """
    return list(_irid.display_names())


def display_transform(rgb, view="aces2", display=None, source="aces2065-1", target="xyz",
                      inverse=False, out=None, threads=0):
    """Scene colours through a display transform (what ``irid display`` does), or back.

    rgb: array (..., 3) of colours of ``source``.
    view: "aces2", the ACES 2.0 Output Transform as OpenColorIO's built-in display transforms
        apply it.
    display: one of :func:`display_names` ("sdr-100nit-rec709", "hdr-1000nit-p3-d65", ...) or
        its full OpenColorIO name.
    source, target: forward, scene colours in ``source`` (any space of :func:`convert`) to
        ``target``: "xyz" (CIE XYZ of the D65 display, 1.0 = 100 cd/m²) or an RGB space, linear
        or encoded. With ``inverse``, display colours in ``source`` ("xyz" or an RGB space) back
        to scene colours in ``target``.
    out, threads: as for :func:`clip`. float64 is computed in double; float32 by the float SIMD
        kernel (within 1e-5 of max(|value|, 1) of the double result) when ``source`` and
        ``target`` are both linear, else in double.

    Raises KeyError for unknown names and ValueError for bad values.

    OpenColorIO's published output of one colour on a 1000 cd/m² P3 display, and back:

    >>> import numpy as np, irid
    >>> xyz = irid.display_transform([0.5, 0.4, 0.3], display="hdr-1000nit-p3-d65")
    >>> np.round(xyz, 5).tolist()
    [0.46537, 0.43853, 0.33688]
    >>> aces = irid.display_transform(xyz, display="hdr-1000nit-p3-d65", source="xyz",
    ...                               target="aces2065-1", inverse=True)
    >>> np.round(aces, 6).tolist()
    [0.5, 0.4, 0.3]
    """
    if display is None:
        raise ValueError("display: give one of irid.display_names()")
    # The transforms already built (each builds its display's tables, several milliseconds), by
    # their arguments as given, as clip keeps its pipelines.
    try:
        key = (view, display, source, target, inverse, inverse.__class__)  # 1 == True: keep the check
        t = _recent.get(key)
    except TypeError:   # an unhashable argument: the checks below refuse it
        key, t = None, None
    if t is None:
        t = _irid.DisplayTransform(_name(view, "view"), _name(display, "display"), _name(source, "source"),
                                   _name(target, "target"), _flag(inverse, "inverse"))
        if key is not None:
            if len(_recent) >= 64:
                _recent.clear()
            _recent[key] = t
    return t.run(rgb, _whole(threads, "threads", 0, _irid.max_threads), out)


_recent = {}


def display_has_scene_value(rgb, view="aces2", display=None, source="xyz", tolerance=1e-5, threads=0):
    """Whether each display colour has a scene value the display transform takes back to it.

    rgb: array (..., 3) of display colours in ``source`` ("xyz", CIE XYZ of the D65 display with
        1.0 = 100 cd/m², or an RGB space, linear or encoded); view, display, threads: as for
        :func:`display_transform`.
    tolerance: how close, of the peak in the display's RGB, a colour the display shows must come
        to count (1e-5: a colour shown and rounded to float32 counts as shown).

    Returns a bool array of shape (...). Where it is False the display never shows the colour to
    ``tolerance``: above the peak's J, beyond what the gamut or chroma compression gives (next to
    white, or for limiting gamuts much wider than AP1), or with its source beyond the AP1 clamp;
    ``display_transform(..., inverse=True)`` then gives the nearest source the chain reaches,
    and showing that misses the colour (docs/DISPLAY.md, "The inverse"). Where it is True the
    forward takes the inverse's result back to the colour: to 1e-10 of the peak inside what the
    chain gives, to ``tolerance`` next to it.

    Raises KeyError for unknown names and ValueError for bad values.

    Mid grey has one; Rec.2020's blue primary at 36 cd/m² has none on a 4000 cd/m² display,
    whose ACES source would lie beyond AP1:

    >>> import irid
    >>> irid.display_has_scene_value([[0.2, 0.2, 0.2], [0.0, 0.0, 0.36]],
    ...                              display="hdr-4000nit-rec2020", source="rec2020-linear").tolist()
    [True, False]
    """
    if display is None:
        raise ValueError("display: give one of irid.display_names()")
    t = _irid.DisplayTransform(_name(view, "view"), _name(display, "display"), _name(source, "source"),
                               "aces2065-1", True)
    return t.scene_values_exist(rgb, _whole(threads, "threads", 0, _irid.max_threads), _number(tolerance, "tolerance"))


def bake_display_lut(display, view="aces2", source="aces2065-1", target=None, size=33, format="clf",
                     threads=0):
    """Bakes a display transform as a 3D LUT (what ``irid lut --view`` writes): a :class:`Lut`.

    display, view, source: as for :func:`display_transform` (forward only).
    target: the display signal's space; default the display's own encoding ("srgb" for
        sdr-100nit-rec709, "rec2100-pq" for hdr-1000nit-rec2020, ...).
    size: nodes per axis, 2 to 129. format: the file the LUT is for, "clf", "cube" or "spi3d",
        which decides its domain as ``irid lut --view`` does: a .clf over light (xyz or a linear
        RGB space) takes a matrix to AP1, where ACES 2.0 clamps its input, then a log2 shaper
        over AP1 [0, the rendering's forward limit] (16 stops); .cube and .spi3d carry neither,
        so they need ``source="acescct"`` (its code values [0, 1]).
    threads: threads to use, 0 for all.

    Raises KeyError for unknown names and ValueError for bad values (a source that is neither
    light nor RGB code values, such as "lab" or "oklab"; a display without an RGB encoding of
    its own and no ``target``; a .cube over a linear source). docs/DISPLAY.md measures the
    LUT's ΔE2000 against the transform.

    >>> import irid
    >>> lut = irid.bake_display_lut("sdr-100nit-rec709", size=17)
    >>> lut.size, lut.shaper, lut.domain, lut.stops     # 1024 = 8 (128 + 768 log(1) / log(100))
    (17, 'log2', (0.0, 1024.0), 16)
    >>> lut.cube_space, lut.matrix.shape                # ACES2065-1 to AP1 first
    ('acescg-linear', (3, 3))
    """
    return _irid.bake_display_lut(_name(view, "view"), _name(display, "display"), _name(source, "source"),
                                  "" if target is None else _name(target, "target"),
                                  _whole(size, "size", 2, 129), _name(format, "format"),
                                  _whole(threads, "threads", 0, _irid.max_threads))

"""The checks of arguments shared by the package's modules, each with its one message."""

from __future__ import annotations

import functools
import numbers
import os

import numpy as np

from . import _irid

__all__: list[str] = []   # private: the modules import what they use by name


def _name(value, what):
    """A name argument: a str (KeyError from the library when it is unknown).

    >>> _name("srgb", "space")
    'srgb'
    >>> _name(3, "space")
    Traceback (most recent call last):
    ...
    ValueError: space: 3 is not a name (str)
    """
    if not isinstance(value, str):
        raise ValueError(f"{what}: {value!r} is not a name (str)")
    return value


def _names(values, what):
    """A list of names (one str alone is refused, not taken as its letters)."""
    if isinstance(values, str):
        raise ValueError(f"{what}: give a list of names, not one string")
    return [_name(v, what) for v in values]


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


def _whole(value, what, lo=None, hi=None):
    """A whole number (not a bool), in [lo, hi] when a range is given.

    >>> _whole(12, "periods")
    12
    >>> _whole(0, "size", 2, 129)
    Traceback (most recent call last):
    ...
    ValueError: size: 0 must be in [2, 129]
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ValueError(f"{what}: {value!r} is not a whole number")
    if lo is not None and not lo <= value <= hi:
        raise ValueError(f"{what}: {value} must be in [{lo}, {hi}]")
    return int(value)


def _number(value, what):
    """A real number (not a bool) as float."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{what}: {value!r} is not a number")
    return float(value)


def _floats(values, what):
    """A sequence of numbers as a list of floats."""
    try:
        return [float(v) for v in values]
    except (TypeError, ValueError):
        raise ValueError(f"{what}: {values!r} is not a sequence of numbers") from None


def _flag(value, what):
    """True or False (a numpy bool too), as bool."""
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{what}: {value!r} is not True or False")
    return bool(value)


def _plain(**arrays):
    """Refuses masked arrays (numpy.ma), whose mask an element-wise call would drop."""
    for name, value in arrays.items():
        if isinstance(value, np.ma.MaskedArray):
            raise ValueError(f"{name}: a masked array (numpy.ma); irid has no masked operations "
                             f"and would drop the mask: pass {name}.filled(value) or {name}.data")


@functools.lru_cache(maxsize=32)
def _named_white(name):
    return _irid.white_point(name)


def _white(white):
    """A reference white given by name ('D65', ...) or as chromaticity (x, y) → (x, y).

    >>> [round(v, 4) for v in _white("D65")]
    [0.3127, 0.329]
    >>> _white((0.3457, 0.3585))
    (0.3457, 0.3585)
    """
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

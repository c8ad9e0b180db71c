"""The renderer from Python: the thesis' scenes (and any scene file or dict) to arrays."""

from __future__ import annotations

import collections
import json
import math
import numbers
import os

from . import _irid
from ._args import _whole

__all__ = [
    "Render",
    "gallery",
    "render",
    "scenes",
]


class Render(collections.namedtuple("Render", ["linear", "display"])):
    """What :func:`render` returns: the pair (``linear``, ``display``), so that
    ``linear, display = irid.render(...)``, with two more attributes.

    linear: the scene-referred image, (height, width, 3) float32: linear RGB of the scene's
        destination space, exposure applied, before the view transform and the gamut clip
        (may leave [0, 1]).
    display: the displayed image: through the scene's view transform (``render.view``: the
        highlight roll-off, or ``"thesis"`` for the clip alone), clipped by the scene's method
        and encoded with the space's transfer function, float32 in [0, 1] (what ``irid render``
        writes to a PNG).
    xyz: CIE XYZ per pixel (the D65 white at Y = 1, exposure applied).
    stats: a dict: camera_rays, rays, out_of_gamut_pixels, seconds, table_seconds, and the
        space, clip, view, width, height, spp and source used.

    >>> import irid
    >>> result = irid.render("oil-slick", width=16, height=12, spp=1)
    >>> linear, display = result
    >>> result.xyz.shape, result.stats["width"], result.stats["spp"]
    ((12, 16, 3), 16, 1)
    """

    def __new__(cls, linear, display, xyz, stats):
        self = super().__new__(cls, linear, display)
        self.xyz = xyz
        self.stats = stats
        return self

    def __reduce__(self):
        return (Render, (self.linear, self.display, self.xyz, self.stats))


def scenes():
    """The built-in scene names: oil-slick, soap-bubbles, morpho.

    >>> import irid
    >>> sorted(irid.scenes())
    ['morpho', 'oil-slick', 'soap-bubbles']
    """
    return _irid.scene_names()


def _json_value(key, value):
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"set[{key!r}]: {value!r} is not a finite number")
    try:
        return json.dumps(value, allow_nan=False)
    except (TypeError, ValueError):
        raise ValueError(f"set[{key!r}]: {value!r} is not a JSON value") from None


def _size(value, what):
    return None if value is None else _whole(value, what, 1, 16384)


def render(scene, width=None, height=None, spp=None, seed=None, set=None, clip=None, threads=0):
    """Renders a scene as ``irid render`` does: ``linear, display = irid.render("oil-slick")``,
    the scene-referred float image and the displayed one (:class:`Render`, which also holds
    ``xyz`` and ``stats``).

    scene: a built-in name (:func:`scenes`), a JSON scene file (str or os.PathLike; relative
        paths inside it are taken from its folder) or a dict of the same JSON (relative paths
        from the current folder).
    width, height: the image size; one alone keeps the scene's aspect ratio.
    spp: samples per pixel (1..1024); seed: the random seed (images are bit-identical for any
        thread count); clip: the gamut method (:func:`clip_methods`).
    set: overrides by key path, as ``--set``: ``{"oil.k1": 2, "render.path": "spectral"}``.
    threads: worker threads, 0 for every core. The GIL is released while rendering.

    Raises ValueError for a bad scene or value (the message names the key path and what is
    allowed), KeyError for an unknown built-in name, OSError for an unreadable scene file.

    A small, quick image (the displayed one is in [0, 1]):

    >>> import irid
    >>> linear, display = irid.render("soap-bubbles", width=16, height=12, spp=1, seed=7)
    >>> linear.shape, display.dtype, bool(0 <= display.min() and display.max() <= 1)
    ((12, 16, 3), dtype('float32'), True)
    """
    if set is not None and not isinstance(set, dict):
        raise ValueError(f"set: {type(set).__name__}; give a dict of key paths to values, such as "
                         f"{{'oil.k1': 2}}")
    overrides = []
    for key, value in (set or {}).items():
        if not isinstance(key, str) or not key or "=" in key or "\0" in key:
            raise ValueError(f"set: key {key!r} must be a key path such as 'oil.k1'")
        overrides.append(f"{key}={_json_value(key, value)}")
    w, h = _size(width, "width"), _size(height, "height")
    if spp is not None:
        # Its range is the scene reader's (render::max_spp), which names it.
        overrides.append(f"image.spp={_whole(spp, 'spp')}")
    if seed is not None:
        if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
            raise ValueError(f"seed: {seed!r} is not a whole number >= 0")
        overrides.append(f"render.seed={int(seed)}")
    if clip is not None:
        if not isinstance(clip, str):
            raise ValueError(f"clip: {clip!r} is not a method name")
        if clip not in _irid.clip_methods():
            raise KeyError(f"clip: {clip!r} is unknown; valid: {', '.join(_irid.clip_methods())}")
        overrides.append(f"render.clip={json.dumps(clip)}")
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or threads < 0:
        raise ValueError(f"threads: {threads!r} must be a whole number >= 0 (0: every core)")

    if isinstance(scene, dict):
        try:
            text = json.dumps(scene, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise ValueError(f"scene: the dict is not JSON ({e})") from None
        args = (text, True, "<dict>", os.getcwd())
    elif isinstance(scene, str) and scene in _irid.scene_names():
        args = (scene, False, scene, "")
    elif isinstance(scene, (str, os.PathLike)):
        path = os.fsdecode(os.fspath(scene))
        if "\0" in path:
            raise ValueError("scene: the path contains a NUL byte")
        if not os.path.exists(path):
            if not path.endswith(".json") and os.sep not in path:
                raise KeyError(f"scene: {path!r} is neither a built-in scene "
                               f"({', '.join(_irid.scene_names())}) nor a file")
            raise FileNotFoundError(f"scene: {path!r}: no such file")
        if not os.path.isfile(path):
            raise IsADirectoryError(f"scene: {path!r} is not a regular file")
        with open(path, "rb") as f:   # OSError (permissions) as Python raises it
            f.read(1)
        args = (path, False, path, "")
    else:
        raise ValueError(f"scene: {scene!r} is neither a name, a path nor a dict")
    linear, display, xyz, stats = _irid.render(*args, overrides, w, h, int(threads))
    return Render(linear, display, xyz, stats)


def gallery(dir, width=1024, height=768, spp=4, figure_width=960, threads=0, pages=None):
    """Writes the gallery page as ``irid gallery -o DIR`` does: the scenes, the figures and
    tables, the colour paths compared and the clip report in DIR/index.html with its images.
    pages ({file: title}, as ``--page FILE=TITLE``) links pages already in DIR. Returns the
    page's path. Takes minutes at the default size; the GIL is released.

    >>> import irid
    >>> irid.gallery("gallery", width=320, height=240, spp=1)   # doctest: +SKIP
    'gallery/index.html'
    """
    args = {}
    for name, value, lo, hi in (("width", width, 32, 4096), ("height", height, 24, 4096),
                                ("spp", spp, 1, 256), ("figure_width", figure_width, 320, 4096),
                                ("threads", threads, 0, 1024)):
        if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not lo <= value <= hi:
            raise ValueError(f"{name}: {value!r} must be a whole number in [{lo}, {hi}]")
        args[name] = int(value)
    try:
        path = os.fsdecode(os.fspath(dir))
    except TypeError:
        raise ValueError(f"dir: {dir!r} is not a folder name") from None
    if not path or "\0" in path:
        raise ValueError("dir: an empty name or a NUL byte; give the folder to write into")
    if pages is None:
        pages = {}
    if not isinstance(pages, dict) or not all(isinstance(k, str) and isinstance(v, str) for k, v in pages.items()):
        raise ValueError(f"pages: {pages!r} must be a dict of file names to titles (strings)")
    index, _ = _irid.gallery(path, args["width"], args["height"], args["spp"], args["figure_width"],
                             args["threads"], list(pages.items()))
    return index

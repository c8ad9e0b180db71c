"""Optics on numpy arrays: materials, the film models, the thesis' closed forms, colour tables.

Angles are in degrees (as ``irid film --angle``), measured in the ambient, in [0, 90);
thicknesses and wavelengths in nm. Colours are relative (the perfect white reflector under the
illuminant has Y = 1) and RGB is linear and unclipped, as ``irid film --color`` prints them.
"""

from __future__ import annotations

import math
import numbers
from typing import NamedTuple

import numpy as np

from . import _irid
from ._args import _flag, _name, _number, _path, _plain, _whole

__all__ = [
    "Film",
    "FilmColorTable",
    "FilmColorTable2D",
    "FilmColors",
    "Material",
    "ThesisFilmTable",
    "film_color",
    "film_reflectance",
    "materials",
    "morpho_effective_thickness",
    "morpho_reflectance",
    "renderer_film_color",
    "renderer_film_models",
    "thesis_effective_thickness",
    "thesis_film_angle",
    "thesis_film_reflectance",
    "thesis_film_table",
    "thesis_matched_k",
    "thesis_multilayer_effective_thickness",
    "thesis_multilayer_reflectance",
    "thesis_phase_change",
    "thesis_unit_peak_k",
]

Material = _irid.Material
FilmColorTable = _irid.FilmColorTable
FilmColorTable2D = _irid.FilmColorTable2D
ThesisFilmTable = _irid.ThesisFilmTable


class FilmColors(NamedTuple):
    """Colours of films: ``xyz`` and ``rgb`` (linear, unclipped), each of shape (..., 3).

    >>> import irid
    >>> xyz, rgb = irid.film_color([("water", 300)])         # a pair, or by name
    >>> colors = irid.film_color([("water", 300)], thickness=[250, 300, 350])
    >>> colors.xyz.shape, colors.rgb.shape
    ((3, 3), (3, 3))
    """

    xyz: np.ndarray
    rgb: np.ndarray


def materials():
    """The named materials of :class:`Material` (air, chitin, fused-silica, gold, ...).

    >>> import irid
    >>> irid.materials()[:4]
    ['air', 'chitin', 'fused-silica', 'gold']
    >>> round(float(irid.Material("water").index([589.0])[0].real), 3)     # n of water
    1.333
    """
    return _irid.material_names()


def _material(value, what):
    if isinstance(value, Material):
        return value
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"{what}: index {value!r} must be finite and > 0")
        return Material.constant(repr(float(value)), float(value))
    if isinstance(value, str):
        try:
            return Material(value)
        except ValueError as e:   # the library's message lists the forms and the names
            if value.strip()[:1].isalpha():   # a name, not a malformed index
                raise KeyError(f"{what}: {e}") from None
            raise ValueError(f"{what}: {e}") from None
    raise ValueError(f"{what}: {value!r} is neither a Material, a name nor an index")


def _optional_number(value, what):
    return None if value is None else _number(value, what)


def _radians(angle, what="angle"):
    """Degrees in [0, 90) → radians, element-wise, with the message the library would give."""
    _plain(**{what: angle})
    a = np.asarray(angle, dtype=np.float64)
    bad = ~(np.isfinite(a) & (a >= 0) & (a < 90))
    if bad.any():
        raise ValueError(f"{what}: {a[bad].flat[0]!r} degrees is outside [0, 90)")
    return np.radians(a)


class Film:
    """A film of one of irid's models (the library's FilmModel), built by the class methods:

    * :meth:`exact`: Fresnel amplitudes, every internal reflection, dispersion, absorption;
    * :meth:`thesis`: Smits 1990 eq. 21/22 with eq. 23/24, the two-beam single film;
    * :meth:`thesis_multilayer`: eq. 25 with eq. 26 (Anderson's N-beam stack in air);
    * :meth:`morpho`: eq. 25 with eq. 29, the Morpho wing, optionally blended (§3.7).

    Every model gives :meth:`reflectance` (a spectrum) and :meth:`color` (over arrays of
    thicknesses and angles). "The thickness" is the first layer's (exact), the film's (thesis),
    a period's (thesis multilayer); the Morpho wing has none.

    >>> import irid
    >>> film = irid.Film.exact([("water", 300)])
    >>> film, film.model, film.thickness
    (<irid.Film exact, thickness=300 nm>, 'exact', 300.0)
    >>> irid.Film.morpho()
    <irid.Film morpho>
    """

    __slots__ = ("_model", "_built")

    def __init__(self, model, built=None):
        if not isinstance(model, _irid.FilmModel):
            raise ValueError("Film: build one with Film.exact, Film.thesis, "
                             "Film.thesis_multilayer or Film.morpho")
        self._model = model
        self._built = built   # (class method, arguments): how a worker process rebuilds it

    def __reduce__(self):
        if self._built is None:
            raise TypeError("irid.Film: only films made by its class methods can be pickled")
        return (_rebuild, self._built)

    @classmethod
    def exact(cls, layers, ambient="air", substrate="air", polarization="unpolarized"):
        """ambient | layers | substrate by the exact optics (Airy for one unpolarised layer, the
        transfer matrix otherwise). layers: [(material, thickness_nm), ...] from the ambient
        side; a material is a :class:`Material`, a name ('water'), an index (1.33) or a text
        ('1.5+0.02i'). polarization: 's', 'p' or 'unpolarized'.

        >>> import irid
        >>> irid.Film.exact([("chitin", 120), ("air", 80), ("chitin", 120)], polarization="s")
        <irid.Film exact, thickness=120 nm>
        """
        if isinstance(layers, tuple) and len(layers) == 2 and not isinstance(layers[0], tuple):
            layers = [layers]
        stack = []
        for i, layer in enumerate(layers):
            try:
                material, thickness = layer
            except (TypeError, ValueError):
                raise ValueError(f"layers[{i}]: {layer!r} is not (material, thickness_nm)") from None
            stack.append((_material(material, f"layers[{i}]"), _number(thickness, f"layers[{i}] thickness")))
        if not isinstance(polarization, str):
            raise ValueError(f"polarization: {polarization!r} is not a name")
        return cls(_irid.film_exact(_material(ambient, "ambient"), stack,
                                    _material(substrate, "substrate"), polarization),
                   ("exact", (list(layers), ambient, substrate, polarization)))

    @classmethod
    def thesis(cls, film, thickness, ambient="air", substrate="air", k=None, phase_change=None):
        """The thesis' single film (eq. 21/22, eq. 23/24). k: the amplitude factor K, default
        the matched K = |r01| + |r12| (the exact film's maxima); k=1 is the thesis as written.
        phase_change: force eq. 21 (True) or eq. 22 (False); default eq. 19's rule.

        >>> import irid
        >>> irid.Film.thesis("water", 300, k=1.0).model
        'thesis'
        """
        if phase_change is not None and not isinstance(phase_change, (bool, np.bool_)):
            raise ValueError(f"phase_change: {phase_change!r} is not True, False or None")
        return cls(_irid.film_thesis(_material(ambient, "ambient"), _material(film, "film"),
                                     _material(substrate, "substrate"), _number(thickness, "thickness"),
                                     _optional_number(k, "k"),
                                     None if phase_change is None else bool(phase_change)),
                   ("thesis", (film, thickness, ambient, substrate, k, phase_change)))

    @classmethod
    def thesis_multilayer(cls, film, thickness, periods, k=None):
        """The thesis' multilayer (eq. 25 with eq. 26): ``periods`` films of ``thickness`` in
        air. k default 2/(periods+1)², for a peak of 1; k=1 is the thesis as written.

        >>> import irid
        >>> irid.Film.thesis_multilayer(1.56, 100, periods=12)
        <irid.Film thesis-multilayer, thickness=100 nm>
        """
        layers = _whole(periods, "periods")
        return cls(_irid.film_thesis_multilayer(_material(film, "film"), _number(thickness, "thickness"),
                                                layers, _optional_number(k, "k")),
                   ("thesis_multilayer", (film, thickness, periods, k)))

    @classmethod
    def morpho(cls, d1=150.0, d2=50.0, n=1.56, periods=12, k=None, blend=False, blend_vary="d1",
               blend_min=50.0, blend_max=150.0, blend_samples=101):
        """The Morpho wing (eq. 25 with eq. 29): d1 the air path and d2 the chitin of a period
        [nm], n chitin's index, ``periods`` mullions, k default 2/(periods+1)². blend: the mean
        over ``blend_samples`` values of d1 (or d2, ``blend_vary='d2'``) from blend_min to
        blend_max nm (§3.7).

        >>> import irid
        >>> irid.Film.morpho(d1=150, d2=50, blend=True).thickness is None
        True
        """
        mullions, samples = _whole(periods, "periods"), _whole(blend_samples, "blend_samples")
        blended = _flag(blend, "blend")
        if not isinstance(blend_vary, str):
            raise ValueError(f"blend_vary: {blend_vary!r} is not a name")
        return cls(_irid.film_morpho(_number(d1, "d1"), _number(d2, "d2"), _number(n, "n"), mullions,
                                     _optional_number(k, "k"), blended, blend_vary,
                                     _number(blend_min, "blend_min"), _number(blend_max, "blend_max"),
                                     samples),
                   ("morpho", (d1, d2, n, periods, k, blend, blend_vary, blend_min, blend_max, blend_samples)))

    @property
    def model(self):
        """'exact', 'thesis', 'thesis-multilayer' or 'morpho'."""
        return self._model.model

    @property
    def thickness(self):
        """The thickness as built [nm] (None for the Morpho wing)."""
        return self._model.thickness if self._model.has_thickness else None

    def __repr__(self):
        t = "" if self.thickness is None else f", thickness={self.thickness:g} nm"
        return f"<irid.Film {self.model}{t}>"

    def reflectance(self, wavelengths, angle=0.0, thickness=None):
        """(R, T) at each wavelength [nm], arrays of the wavelengths' shape. T is the power
        entering the substrate (exact model; 0 for the thesis' closed forms). thickness
        replaces the film's (not for the Morpho wing).

        A quarter-wave layer (n t = λ/4) in a medium of index 1 reflects ((1 − n²)/(1 + n²))²:

        >>> import irid
        >>> R, T = irid.Film.exact([(1.5, 100.0)], ambient=1.0, substrate=1.0).reflectance([600.0])
        >>> round(float(R[0]), 6), round((1.25 / 3.25) ** 2, 6), round(float(R[0] + T[0]), 9)
        (0.147929, 0.147929, 1.0)
        """
        a = float(_radians(_number(angle, "angle")))
        if thickness is not None and not self._model.has_thickness:
            raise ValueError("thickness: the Morpho wing has none (d1 and d2 set it)")
        return self._model.spectrum(wavelengths, a, _optional_number(thickness, "thickness"))

    def color(self, thickness=None, angle=0.0, illuminant="D65", observer="cie1931", rgb="srgb",
              integration="sum"):
        """The colours at every (thickness, angle) of the two arrays broadcast together:
        :class:`FilmColors` (xyz, rgb) of shape broadcast + (3,). thickness default the film's.
        Each angle's Fresnel terms are computed once for all its thicknesses.

        integration: "sum" (the CIE 1 nm sum) or "fourier" (the exact single film's Airy series
        against the transformed matching functions, ``irid film --color --integration
        fourier``): one lossless layer, unpolarised, else ValueError; an unknown name is a
        KeyError.

        >>> import irid
        >>> film = irid.Film.exact([("water", 300)])
        >>> film.color(thickness=[100, 200, 300], angle=[[0], [45]]).rgb.shape   # 2 angles × 3
        (2, 3, 3)
        """
        if thickness is None:
            thickness = self._model.thickness
        elif not self._model.has_thickness:
            raise ValueError("thickness: the Morpho wing has none (d1 and d2 set it)")
        _plain(thickness=thickness)
        t = np.asarray(thickness, dtype=np.float64)
        a = _radians(angle)
        t, a = np.broadcast_arrays(t, a)
        for name, v in (("illuminant", illuminant), ("observer", observer), ("rgb", rgb),
                        ("integration", integration)):
            if not isinstance(v, str):
                raise ValueError(f"{name}: {v!r} is not a name")
        xyz, out = self._model.colors(np.ascontiguousarray(t).ravel(), np.ascontiguousarray(a).ravel(),
                                      illuminant, observer, rgb, integration)
        shape = t.shape + (3,)
        return FilmColors(xyz.reshape(shape), out.reshape(shape))

    def effective_thickness(self, angle=0.0):
        """Eq. 29's t_θ [nm] of the Morpho wing at an angle (array); None for other models.

        At normal incidence t = d₁ + d₂ n = 150 + 50 · 1.56:

        >>> import irid
        >>> irid.Film.morpho().effective_thickness([0.0]).tolist()
        [228.0]
        """
        if self._model.has_thickness:
            return None
        a = _radians(angle)
        return np.vectorize(self._model.effective_thickness, otypes=[np.float64])(a)

    def color_table(self, max_thickness, step=1.0, min_thickness=0.0, angle=0.0,
                    illuminant="D65", observer="cie1931", rgb="srgb"):
        """The thesis' §3.3 colour table of this film at one angle: thickness → colour every
        ``step`` nm (shrunk to divide the range), looked up linearly by ``table.at(t)`` →
        (xyz, rgb). Thicknesses outside the range clamp to its ends.

        >>> import numpy as np, irid
        >>> film = irid.Film.exact([("water", 300)])
        >>> xyz, rgb = film.color_table(500).at(250)        # a node: the film's own colour
        >>> bool(np.allclose(xyz, film.color(250).xyz))
        True
        """
        if not self._model.has_thickness:
            raise ValueError("color_table: the Morpho wing has no thickness to index")
        return _irid.film_color_table(self._model, _number(min_thickness, "min_thickness"),
                                      _number(max_thickness, "max_thickness"), _number(step, "step"),
                                      float(_radians(_number(angle, "angle"))), illuminant, observer, rgb)

    def color_table_2d(self, max_thickness, step=2.0, max_angle=80.0, cos_steps=40,
                       illuminant="D65", observer="cie1931", rgb="srgb"):
        """Thickness × cos θ → colour (the renderer's table for the exact film): thicknesses 0 to
        max every ``step`` nm, cos θ from cos(max_angle) to 1 in ``cos_steps`` steps; bilinear
        ``table.at(t, cos_theta)`` → (xyz, rgb).

        >>> import irid
        >>> table = irid.Film.exact([("water", 300)]).color_table_2d(500, step=10, cos_steps=8)
        >>> xyz, rgb = table.at(250, 1.0)
        >>> xyz.shape, table.cos_count
        ((1, 3), 9)
        """
        if not self._model.has_thickness:
            raise ValueError("color_table_2d: the Morpho wing has no thickness to index")
        steps = _whole(cos_steps, "cos_steps")
        return _irid.film_color_table_2d(self._model, _number(max_thickness, "max_thickness"),
                                         _number(step, "step"),
                                         float(_radians(_number(max_angle, "max_angle"), "max_angle")),
                                         steps, illuminant, observer, rgb)


def _rebuild(method, args):
    return getattr(Film, method)(*args)


def _film(stack, ambient, substrate, polarization):
    if isinstance(stack, Film):
        return stack
    return Film.exact(stack, ambient=ambient, substrate=substrate, polarization=polarization)


def film_reflectance(stack, wavelengths, angle=0.0, polarization="unpolarized", ambient="air",
                     substrate="air"):
    """The spectrum (R, T) of a stack at each wavelength [nm]: ``stack`` is a :class:`Film` or
    the layers of an exact one, [(material, thickness_nm), ...] between ``ambient`` and
    ``substrate`` (polarization 's', 'p' or 'unpolarized').

    >>> import numpy as np, irid
    >>> R, T = irid.film_reflectance([(1.5, 100.0)], [600.0], ambient=1.0, substrate=1.0)
    >>> np.round(R, 6).tolist()                   # quarter-wave: (1.25 / 3.25)²
    [0.147929]
    """
    if isinstance(stack, Film) and polarization != "unpolarized":
        raise ValueError("polarization: give it to Film.exact when the stack is a Film")
    return _film(stack, ambient, substrate, polarization).reflectance(wavelengths, angle)


def film_color(stack, thickness=None, angle=0.0, illuminant="D65", observer="cie1931", rgb="srgb",
               ambient="air", substrate="air", integration="sum"):
    """Colours of a stack (as :func:`film_reflectance`) over arrays of thicknesses (of the first
    layer) and angles [degrees] broadcast together: :class:`FilmColors` (xyz, rgb).
    integration: "sum" or "fourier" (:meth:`Film.color`).

    >>> import irid
    >>> colors = irid.film_color([("water", 300)], thickness=[100, 200], angle=30.0)
    >>> colors.xyz.shape
    (2, 3)
    """
    return _film(stack, ambient, substrate, "unpolarized").color(thickness, angle, illuminant, observer, rgb,
                                                                 integration)


def renderer_film_models():
    """The renderers' thin-film models: 'gltf' (KHR_materials_iridescence), 'belcour' (Belcour &
    Barla 2017), 'cycles' (Blender Cycles).

    >>> import irid
    >>> irid.renderer_film_models()
    ['gltf', 'belcour', 'cycles']
    """
    return _irid.renderer_film_models()


def renderer_film_color(model, film, thickness, angle=0.0, ambient="air", substrate="air"):
    """The colour a renderer's thin-film model gives ambient | film | substrate over arrays of
    thicknesses [nm] and angles [degrees] broadcast together, as ``irid film --model MODEL``:
    :class:`FilmColors` (xyz relative to D65, rgb the model's linear Rec.709). The film must be
    real (k = 0); a metal substrate takes its n + ik per RGB channel.

    >>> import irid
    >>> irid.renderer_film_color("gltf", "water", [100, 300], angle=20.0).rgb.shape
    (2, 3)
    """
    if not isinstance(model, str):
        raise ValueError(f"model: {model!r} is not a name")
    _plain(thickness=thickness)
    t = np.asarray(thickness, dtype=np.float64)
    a = _radians(angle)
    t, a = np.broadcast_arrays(t, a)
    xyz, rgb = _irid.renderer_film_colors(model, _material(ambient, "ambient"), _material(film, "film"),
                                          _material(substrate, "substrate"),
                                          np.ascontiguousarray(t).ravel(), np.ascontiguousarray(a).ravel())
    shape = t.shape + (3,)
    return FilmColors(xyz.reshape(shape), rgb.reshape(shape))


# --- The thesis' closed forms, element-wise with numpy broadcasting -------------------------

def thesis_phase_change(n_ambient, n_film, n_substrate):
    """Eq. 19–20: whether the film's two beams differ by a π phase change (eq. 21) or not.

    A soap film in air changes phase at one face; oil (1.33 < n < 1.5) on glass at both:

    >>> import irid
    >>> bool(irid.thesis_phase_change(1.0, 1.33, 1.0)), bool(irid.thesis_phase_change(1.0, 1.4, 1.5))
    (True, False)
    """
    _plain(n_ambient=n_ambient, n_film=n_film, n_substrate=n_substrate)
    return _irid.thesis_phase_change(n_ambient, n_film, n_substrate)


def thesis_film_reflectance(wavelength, thickness, n_film=1.33, phase_change=True, k=1.0):
    """Eq. 21 (phase_change) or eq. 22 at normal incidence: ρ = [K cos(2πtn/λ + π/2)]² or
    [K cos(2πtn/λ)]²; with t = t′ (eq. 24) and n = 1 the reflectance at any angle.

    At t n = λ/4 the film with the phase change reflects K² (cos π)² and the other none:

    >>> import irid
    >>> round(float(irid.thesis_film_reflectance(532.0, 100.0, 1.33)), 9)
    1.0
    >>> round(float(irid.thesis_film_reflectance(532.0, 100.0, 1.33, phase_change=False)), 9)
    0.0
    """
    _plain(wavelength=wavelength, thickness=thickness, n_film=n_film, phase_change=phase_change, k=k)
    return _irid.thesis_film_reflectance(wavelength, thickness, n_film, phase_change, k)


def thesis_film_angle(angle, n_film, n_ambient=1.0):
    """Snell's law for eq. 23: the angle inside the film [degrees] for ``angle`` in the ambient
    (90 beyond the critical angle).

    >>> import math, irid
    >>> round(float(irid.thesis_film_angle(30.0, 1.5)), 4), round(math.degrees(math.asin(1 / 3)), 4)
    (19.4712, 19.4712)
    """
    _plain(n_film=n_film, n_ambient=n_ambient)
    return np.degrees(_irid.thesis_film_angle(_radians(angle), n_film, n_ambient))


def thesis_effective_thickness(thickness, n_film, angle_in_film):
    """Eq. 23–24: t′ = t n cos θ [nm], θ the angle inside the film [degrees, 0–90].

    >>> import irid
    >>> round(float(irid.thesis_effective_thickness(100.0, 1.5, 60.0)), 9)    # 100 · 1.5 · ½
    75.0
    """
    _plain(thickness=thickness, n_film=n_film, angle_in_film=angle_in_film)
    a = np.asarray(angle_in_film, dtype=np.float64)
    if not (np.isfinite(a) & (a >= 0) & (a <= 90)).all():
        raise ValueError("angle_in_film: must be finite degrees in [0, 90]")
    return _irid.thesis_effective_thickness(thickness, n_film, np.radians(a))


def thesis_multilayer_reflectance(wavelength, effective_thickness, periods=12, k=1.0):
    """Eq. 25 (after Anderson 1942): I = ½K (sin(2π(l+1)t/λ) / sin(2πt/λ))², l = periods, t the
    effective thickness of a period (eq. 26 or 29); its limit where sin(2πt/λ) = 0.

    Where t = λ/2 the ratio's limit is (l + 1)², and K = 2/(l + 1)² makes the peak 1:

    >>> import irid
    >>> float(irid.thesis_multilayer_reflectance(500.0, 250.0, periods=12, k=1.0))
    84.5
    >>> round(float(irid.thesis_multilayer_reflectance(500.0, 250.0, 12, k=2 / 169)), 9)
    1.0
    """
    _plain(wavelength=wavelength, effective_thickness=effective_thickness, periods=periods, k=k)
    return _irid.thesis_multilayer_reflectance(wavelength, effective_thickness, periods, k)


def thesis_multilayer_effective_thickness(thickness, n, angle):
    """Eq. 26: t_θ = t (n² − sin²θ)^½ [nm], θ the angle in air [degrees].

    >>> import irid
    >>> float(irid.thesis_multilayer_effective_thickness(100.0, 1.5, 0.0))
    150.0
    """
    _plain(thickness=thickness, n=n)
    return _irid.thesis_multilayer_effective_thickness(thickness, n, _radians(angle))


def morpho_effective_thickness(angle, d1=150.0, d2=50.0, n=1.56):
    """Eq. 29: t_θ = d₁ cos θ + d₂ (n² − sin²θ)^½ [nm], θ the angle in air [degrees].

    >>> import irid
    >>> float(irid.morpho_effective_thickness(0.0))         # 150 + 50 · 1.56
    228.0
    """
    _plain(d1=d1, d2=d2, n=n)
    return _irid.morpho_effective_thickness(_radians(angle), d1, d2, n)


def morpho_reflectance(wavelength, angle=0.0, d1=150.0, d2=50.0, n=1.56, periods=12, k=None):
    """Eq. 25 with eq. 29: the Morpho wing's reflectance, k default 2/(periods+1)² (peak 1).

    The wing's first peak at normal incidence is at λ = 2 t = 456 nm:

    >>> import irid
    >>> round(float(irid.morpho_reflectance(456.0)), 9)
    1.0
    """
    if k is None:
        k = _irid.thesis_unit_peak_k(_whole(periods, "periods"))
    return thesis_multilayer_reflectance(wavelength, morpho_effective_thickness(angle, d1, d2, n),
                                         periods, k)


def thesis_matched_k(film, ambient="air", substrate="air", wavelength=555.0):
    """K = |r01| + |r12| (normal-incidence Fresnel amplitudes at ``wavelength``): eq. 21/22 then
    peak where the exact film does (0.286 for water in air).

    >>> import irid
    >>> round(irid.thesis_matched_k("water"), 3)
    0.286
    """
    return _irid.thesis_matched_k(_material(ambient, "ambient"), _material(film, "film"),
                                  _material(substrate, "substrate"), _number(wavelength, "wavelength"))


def thesis_unit_peak_k(periods):
    """K = 2/(l+1)², for which eq. 25 peaks at 1.

    >>> import irid
    >>> irid.thesis_unit_peak_k(12) == 2 / 13 ** 2
    True
    """
    return _irid.thesis_unit_peak_k(_whole(periods, "periods"))


def thesis_film_table(phase_change=True, max_effective_thickness=2000.0, step=1.0, illuminant="D65",
                      observer="cie1931"):
    """The thesis' §3.3 table for one phase case: XYZ of a film of index 1 at normal incidence,
    K = 1, every ``step`` nm of effective thickness t′; ``table.at(t_eff, k)`` → XYZ (scaled by
    K²). Any film of that phase case is looked up by its t′ (eq. 24).

    At t′ = 0 the film with the phase change reflects nothing, the other everything (the white):

    >>> import numpy as np, irid
    >>> irid.thesis_film_table(True, 500).at(0.0, 1.0).tolist()
    [[0.0, 0.0, 0.0]]
    >>> np.round(irid.thesis_film_table(False, 500).at(0.0, 1.0), 4).tolist()
    [[0.9505, 1.0, 1.0888]]
    """
    return _irid.thesis_film_table(_flag(phase_change, "phase_change"), _number(max_effective_thickness, "max_effective_thickness"),
                                   _number(step, "step"), illuminant, observer)


def write_film_shader(directory, lang="glsl", illuminant="D65", space="srgb"):
    """Writes the exact film colour as a shader chunk and its table (``irid shader``).

    directory: the folder (created if missing). lang: "glsl", a GLSL ES 3.00 chunk defining
    three.js's ``vec3 evalIridescence(float outsideIOR, float eta2, float cosTheta1, float
    thinFilmThickness, vec3 baseF0)`` with one uniform, ``iridFilmTable``; or "wgsl", the same in
    WGSL (``irid_eval`` taking the table as a ``texture_2d<f32>``, and ``evalIridescence`` reading
    it from ``@group(0) @binding(0)``). illuminant: as :func:`film_color` takes it; space: a
    working space by its name or NAME-linear (CIE 1931 observer). The chunk returns linear RGB
    of that space, a perfect mirror (1, 1, 1); names are recorded one way (``D50``,
    ``display-p3-linear``), whatever their case.

    Returns the paths written: irid_iridescence.glsl (or .wgsl), irid_film_table.f32
    (little-endian float32 RGBA texels, row-major) and irid_film_table.json (width, height,
    uniform, illuminant, space, primaries, white, filter), replaced as a set. Raises KeyError for
    an unknown language, illuminant or space, ValueError for an encoding (rec2100-pq, acescct:
    the chunk's values are linear), OSError when a file cannot be written.

    >>> import json, os, tempfile, irid
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     paths = irid.write_film_shader(folder)
    ...     table = json.load(open(paths[2]))
    ...     [os.path.basename(p) for p in paths], os.path.getsize(paths[1]) == table["width"] * table["height"] * 16
    (['irid_iridescence.glsl', 'irid_film_table.f32', 'irid_film_table.json'], True)
    """
    return _irid.write_film_shader(_path(directory), _name(lang, "lang"),
                                   _name(illuminant, "illuminant"), _name(space, "space"))

"""irid: interference colours and gamut mapping, on numpy arrays.

The library behind the ``irid`` command (C++20), for Python:

* colour: :func:`convert` between every space of ``irid convert``, :func:`delta_e`, the CIE
  observers (:func:`cmfs`) and illuminants (:func:`illuminant`, :func:`blackbody`),
  :func:`spectrum_to_xyz` for many spectra at once, and the thesis' primaries transform
  (:func:`primaries_transform`, Smits 1990, Figure 2);
* gamut mapping: :func:`clip` and :func:`clip_image` with every method and parameter of
  ``irid clip`` (:func:`clip_methods`, :func:`clip_parameters`), baked as 3D LUTs
  (:func:`bake_lut`) and OpenColorIO looks (:func:`write_ocio_config`), and :func:`clip_report`;
* optics: :class:`Material` (by name, constant, Cauchy, Sellmeier, CSV), :class:`Film` (the
  exact optics, the thesis' single film, multilayer and Morpho wing) with its spectra and
  colours over arrays of thicknesses and angles, :func:`film_reflectance`, :func:`film_color`,
  the thesis' closed forms (eq. 19–29: :func:`thesis_film_reflectance`,
  :func:`thesis_multilayer_reflectance`, :func:`morpho_reflectance`, ...) and colour tables
  (:meth:`Film.color_table`, :func:`thesis_film_table`); the renderers' thin-film colour models
  (glTF, Belcour & Barla, Cycles: :func:`renderer_film_color`, :func:`renderer_film_models`);
* images: :func:`read_image` and :func:`write_image` through OpenImageIO, the space a file
  says it holds (:func:`image_space`) and ICC profiles (:func:`icc_profile`,
  :func:`read_icc_profile`);
* rendering: :func:`render` of the thesis' scenes (:func:`scenes`), a scene file or a dict.

Arrays in, arrays out: a colour argument is any array of shape (..., 3), float32 or float64
(anything else is taken as float64), and the result has the same shape. A float32 C-contiguous
array is read without a copy and gives float32; ``out=`` writes the result into an existing
array (it may be the input itself). Long calls release the GIL.

Errors: ``ValueError`` for bad values (with the library's message), ``KeyError`` for unknown
names (listing the valid ones), ``OSError`` for files.

Each concern is a module of its own, whose names the package re-exports: ``_color``, ``_gamut``,
``_io``, ``_optics`` and ``_render`` (around the extension ``_irid``); the docstrings'
examples run as tests (``pytest --doctest-modules`` on the package).

Example:

>>> import numpy as np, irid
>>> rgb = np.array([[1.2, -0.1, 0.3], [0.5, 0.5, 0.5]], dtype=np.float32)
>>> irid.clip(rgb, "oklab-cusp", out=rgb) is rgb      # in place, sRGB linear
True
>>> bool(((rgb >= 0) & (rgb <= 1)).all())
True
>>> lab = irid.convert(rgb, "srgb-linear", "oklab")
>>> lab.shape, lab.dtype
((2, 3), dtype('float32'))
"""

from ._color import (blackbody, cmfs, color_spaces, convert, delta_e, illuminant,
                     primaries_transform, rgb_color_spaces, spectrum_to_xyz, white_point)
from ._display import bake_display_lut, display_has_scene_value, display_names, display_transform
from ._gamut import (Lut, bake_lut, clip, clip_branches, clip_image, clip_methods,
                     clip_parameters, clip_report, simd_target, write_ocio_config)
from ._io import icc_profile, image_space, read_icc_profile, read_image, write_image
from ._optics import (Film, FilmColors, FilmColorTable, FilmColorTable2D, Material,
                      ThesisFilmTable, film_color, film_reflectance, materials,
                      renderer_film_color, renderer_film_models,
                      morpho_effective_thickness, morpho_reflectance, thesis_effective_thickness,
                      thesis_film_angle, thesis_film_reflectance, thesis_film_table,
                      thesis_matched_k, thesis_multilayer_effective_thickness,
                      thesis_multilayer_reflectance, thesis_phase_change, thesis_unit_peak_k,
                      write_film_shader)
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
    "bake_display_lut",
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
    "display_has_scene_value",
    "display_names",
    "display_transform",
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
    "write_film_shader",
    "write_image",
    "write_ocio_config",
]

__version__ = "0.1.0"

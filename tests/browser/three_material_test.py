#!/usr/bin/env python3
"""web/irid-three.js patches a real three.js MeshPhysicalMaterial: a sphere rendered in headless
Chromium carries irid's exact film colours, and the unpatched material's differ.

    python3 three_material_test.py <path-to-irid> [--table DIR]

At sample pixels of the unit sphere (cos θ = √(1 − x² − y²) from the pixel's centre):
- isolated (three's material.iridescenceFresnel as the output): the patched material gives the
  exact film (irid.Film.exact, ambient 1, film n = iridescenceIOR, base n = the material's ior,
  thickness = the range's maximum) and, with a thickness map, the thickness three.js derives
  from its G channel; the unpatched material gives three's own chunk's colours, visibly other;
- lit (black base colour, metalness 0, one directional light from the camera): the specular's
  colour is the exact film's times a grey factor, and not the unpatched material's.
Needs the Python module on PYTHONPATH, irid (for `irid shader`, unless --table is given), node,
web/node_modules and chromium (scripts/install-deps). Exits 1 when a check fails.
"""
import argparse
import os
import sys
import tempfile

import numpy as np

import irid
from browser import Checks, delta_e, irid_shader, run_page

SIZE = 128
FILM_IOR = 1.33     # iridescenceIOR (a soap film)
BASE_IOR = 1.5      # the material's ior: three's dielectric F0 = 0.04, the base under the film
RANGE = [100.0, 420.0]  # iridescenceThicknessMinimum, Maximum: without a map three.js uses the maximum
MAP_GREEN = 128     # the thickness map's G: thickness = min + (max − min) G/255

# The chunk meets ΔE2000 0.5 on its own (film_grid_test); the sphere's normals are interpolated
# over a 512 × 256 tessellation, which moves cos θ by < 1e-4 at the samples: 0.6 in all.
ISOLATED_MAX_DE = 0.6
# The lit specular is iridescenceFresnel times a grey factor (GGX D·V·NdotL, irradiance and
# three's grey multiple-scattering compensation): its colour, scaled by the best factor, must
# be the film's to 1 % of its magnitude (float noise and the chunk's own error are far below).
LIT_MAX_RELATIVE = 0.01
# The unpatched material (three's glTF model) must be told apart: ΔE2000 well above the noise.
DIFFERENT_MIN_DE = 1.0
# ... and be three's own evalIridescence (film_grid_test checks it against irid's CPU port),
# evaluated directly at the samples' cos θ: equal but for the tessellation (0.05 seen; 0.2).
UNPATCHED_MAX_DE = 0.2

check = Checks()


def samples():
    """Pixels along a diagonal and an axis, at radii 0.05–0.85 (0–58°)."""
    pixels = []
    for r in np.linspace(0.05, 0.85, 9):
        for direction in ((1.0, 0.0), (0.6, 0.8), (-0.8, -0.6)):
            x = int((r * direction[0] + 1) / 2 * SIZE)
            y = int((r * direction[1] + 1) / 2 * SIZE)
            pixels.append((x, y))
    return pixels


def cos_theta(pixels):
    p = np.array(pixels, dtype=np.float64)
    ndc = (p + 0.5) / SIZE * 2.0 - 1.0
    return np.sqrt(1.0 - (ndc ** 2).sum(axis=1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("irid")
    parser.add_argument("--table", help="a folder with irid's chunk and table (default: irid shader writes one)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="irid-three-material-") as work:
        table = args.table if args.table else irid_shader(args.irid, os.path.join(work, "shader"), check)
        if table is None:
            return check.finish()
        pixels = samples()
        out = run_page(work, "/tests/three_material_page.js",
                       {"table": "/table/", "size": SIZE, "filmIOR": FILM_IOR, "baseIOR": BASE_IOR,
                        "thicknessMinimum": RANGE[0], "thicknessMaximum": RANGE[1], "mapGreen": MAP_GREEN,
                        "samples": pixels, "cosines": cos_theta(pixels).tolist()},
                       {"table": table}, timeout=300)

    c = cos_theta(pixels)
    angles = np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))
    film = irid.Film.exact([(FILM_IOR, RANGE[1])], ambient=1.0, substrate=BASE_IOR)
    expected = film.color(thickness=RANGE[1], angle=angles).rgb
    map_thickness = RANGE[0] + (RANGE[1] - RANGE[0]) * MAP_GREEN / 255.0
    expected_map = film.color(thickness=map_thickness, angle=angles).rgb
    print(f"{len(pixels)} pixels at {angles.min():.1f}-{angles.max():.1f} deg; film n {FILM_IOR} on n {BASE_IOR}, "
          f"{RANGE[1]:.0f} nm (range max) and {map_thickness:.1f} nm (map G {MAP_GREEN})")

    # Five materials whose shaders differ (isolated patched, unpatched, patched with a map; lit
    # patched, unpatched): a cache key that let one reuse another's program would show fewer.
    check(out["programs"] == 5, "three.js compiled one program per variant (customProgramCacheKey)",
          f"{out['programs']} programs")
    iso = {k: np.array(v) for k, v in out["isolated"].items()}
    de = delta_e(iso["patched"], expected)
    check(de.max() <= ISOLATED_MAX_DE, f"patched iridescenceFresnel = the exact film (ΔE2000 <= {ISOLATED_MAX_DE})",
          f"mean {de.mean():.3f}, max {de.max():.3f}")
    de = delta_e(iso["patchedMap"], expected_map)
    check(de.max() <= ISOLATED_MAX_DE,
          f"with iridescenceThicknessMap: the exact film at the map's thickness (ΔE2000 <= {ISOLATED_MAX_DE})",
          f"mean {de.mean():.3f}, max {de.max():.3f}")
    de = delta_e(iso["unpatched"], expected)
    check(de.mean() >= DIFFERENT_MIN_DE, f"the unpatched material's differ (mean ΔE2000 >= {DIFFERENT_MIN_DE})",
          f"mean {de.mean():.3f}, max {de.max():.3f}")
    stock = np.array(out["stock"])
    de = delta_e(iso["unpatched"], stock)
    check(de.max() <= UNPATCHED_MAX_DE,
          f"the unpatched material's are three's own chunk at the same angles (ΔE2000 <= {UNPATCHED_MAX_DE})",
          f"mean {de.mean():.3f}, max {de.max():.3f}")

    lit = {k: np.array(v) for k, v in out["lit"].items()}

    def colour_residual(pixels_rgb, film_rgb):
        scale = (pixels_rgb * film_rgb).sum(axis=1) / (film_rgb * film_rgb).sum(axis=1)
        residual = np.linalg.norm(pixels_rgb - scale[:, None] * film_rgb, axis=1)
        return residual / np.linalg.norm(pixels_rgb, axis=1), scale

    lit_ok = np.linalg.norm(lit["patched"], axis=1) > 0
    check(lit_ok.all(), "the lit sphere is lit at every sample", f"{(~lit_ok).sum()} black samples")
    rel, scale = colour_residual(lit["patched"], expected)
    check(rel.max() <= LIT_MAX_RELATIVE,
          f"lit patched specular = grey factor x the exact film (relative residual <= {LIT_MAX_RELATIVE})",
          f"max {rel.max():.4f}, factors {scale.min():.3f}-{scale.max():.3f}")
    de = delta_e(lit["unpatched"] / scale[:, None], expected)
    check(de.mean() >= DIFFERENT_MIN_DE,
          f"lit unpatched, with the same factors, is not the exact film (mean ΔE2000 >= {DIFFERENT_MIN_DE})",
          f"mean {de.mean():.3f}, max {de.max():.3f}")

    return check.finish()


if __name__ == "__main__":
    sys.exit(main())

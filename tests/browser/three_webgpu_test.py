#!/usr/bin/env python3
"""irid's TSL node (web/irid-three-webgpu.js, from `irid shader --lang wgsl`) in three.js's
WebGPURenderer on headless Chromium's WebGPU (SwiftShader's Vulkan adapter):

1. the node over the whole domain of tests/browser/film_grid_test.py (ambients 1-2, films 1-3,
   bases 1-3, 0-89.99 deg, 0-30 um) against the alias-free exact film: mean ΔE2000 <= 0.01, max
   <= 0.5 (issue 38's goal);
2. a MeshPhysicalNodeMaterial patched by applyIridescenceNode: its lit specular is a grey factor
   times the exact film at each pixel's angle, the unpatched material's is not, and clone()
   keeps the patch.

    python3 three_webgpu_test.py <path-to-irid>

Needs the Python module on PYTHONPATH (ctest sets it), node + web/node_modules and chromium.
Prints what it measured; exits 1 when a check fails, 2 when it cannot run.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

import irid
from browser import Checks, delta_e, run_page
from film_grid_test import DOMAIN_MAX, DOMAIN_MEAN, domain_grid, stats

SIZE = 128
FILM_IOR, BASE_IOR, THICKNESS = 1.33, 1.5, 420.0
# As tests/browser/three_material_test.py: the lit specular is the film's colour times a grey
# factor (the GGX lobe and the light), to the tessellation's error.
LIT_MAX_RELATIVE = 0.01
DIFFERENT_MIN_DE = 0.5
SAME = 1e-6

check = Checks()


def samples():
    """Pixels on the sphere from its centre to near its rim, along the diagonal."""
    return [[int(SIZE / 2 + k), int(SIZE / 2 + k)] for k in range(0, int(SIZE * 0.33), 4)]


def cos_theta(pixels):
    p = np.array(pixels, dtype=np.float64)
    ndc = (p + 0.5) / SIZE * 2.0 - 1.0
    return np.sqrt(1.0 - (ndc ** 2).sum(axis=1))


def main():
    cli = os.path.abspath(sys.argv[1])
    params, exact, labels = domain_grid()
    pixels = samples()
    with tempfile.TemporaryDirectory(prefix="irid-three-webgpu-") as work:
        folder = os.path.join(work, "wgsl")
        run = subprocess.run([cli, "shader", "--lang", "wgsl", "-o", folder], capture_output=True, text=True,
                             timeout=300)
        check(run.returncode == 0, "irid shader --lang wgsl writes the chunk", f"exit {run.returncode} {run.stderr.strip()}")
        if run.returncode != 0:
            return check.finish()
        params.astype("<f4").tofile(os.path.join(work, "params.f32"))
        out = run_page(work, "/tests/three_webgpu_page.js",
                       {"wgsl": "/wgsl/", "params": "/work/params.f32",
                        "sphere": {"size": SIZE, "filmIOR": FILM_IOR, "baseIOR": BASE_IOR,
                                   "thicknessMaximum": THICKNESS, "samples": pixels}},
                       {"wgsl": folder, "work": work}, timeout=600)
    print(f"three.js WebGPURenderer backend: {out['backend']}")
    got = np.array(out["grid"]).reshape(-1, 3)
    de = delta_e(got, exact)
    w = int(de.argmax())
    check(de.mean() <= DOMAIN_MEAN and de.max() <= DOMAIN_MAX,
          f"the TSL node over the whole domain vs the alias-free exact film (mean ΔE2000 <= {DOMAIN_MEAN}, "
          f"max <= {DOMAIN_MAX})",
          f"{len(params)} sets: {stats(de)} (worst at {labels[w]}, {params[w, 3]:g} nm, "
          f"{np.degrees(np.arccos(min(params[w, 2], 1.0))):.3f} deg)")

    c = cos_theta(pixels)
    angles = np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))
    film = irid.Film.exact([(FILM_IOR, THICKNESS)], ambient=1.0, substrate=BASE_IOR)
    expected = film.color(thickness=THICKNESS, angle=angles).rgb
    s = {k: np.array(v) for k, v in out["sphere"].items()}

    def residual(rgb):
        scale = (rgb * expected).sum(axis=1) / (expected * expected).sum(axis=1)
        return np.linalg.norm(rgb - scale[:, None] * expected, axis=1) / np.linalg.norm(rgb, axis=1), scale

    rel, scale = residual(s["patched"])
    check(np.linalg.norm(s["patched"], axis=1).min() > 0 and rel.max() <= LIT_MAX_RELATIVE,
          f"lit MeshPhysicalNodeMaterial with the node: specular = grey factor x the exact film "
          f"(relative residual <= {LIT_MAX_RELATIVE}, {len(pixels)} pixels at {angles.min():.0f}-{angles.max():.0f} deg)",
          f"max {rel.max():.4f}, factors {scale.min():.3f}-{scale.max():.3f}")
    de = delta_e(s["unpatched"] / scale[:, None], expected)
    check(de.mean() >= DIFFERENT_MIN_DE, f"the unpatched material's is three's own film (mean ΔE2000 >= {DIFFERENT_MIN_DE})",
          f"mean {de.mean():.3f}")
    check(np.abs(s["clone"] - s["patched"]).max() <= SAME, "clone() keeps the node", f"max {np.abs(s['clone'] - s['patched']).max():.2g}")
    return check.finish()


if __name__ == "__main__":
    sys.exit(main())

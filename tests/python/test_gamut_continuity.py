"""Continuity of every clip method through Python, on float32 arrays (the SIMD kernels) and
float64 arrays (the double methods): tests/gamut/continuity_test.cpp's walk in a smaller form.

Random segments of bright, near-white, near-black, saturated and HDR colours are clipped at 49
points each; every step whose output moves by more than ΔE2000 2 is bisected (all of them at
once, one irid.clip call per round) down to 1e-10 (float64) or to adjacent floats (float32),
and a step still above ΔE2000 1 there is a jump. A jump must be one that GAMUT.md lists as
forced by the method's definition ("Where a method may jump"): between colours whose branches
of the definition differ (irid.clip_branches)."""

import numpy as np
import pytest

import irid

STEPS = 48


def segments(rng, n, peak):
    """n segments' end points, (n, 2, 3), a fifth from each family, in units of the peak."""
    ends = []
    for k in range(n):
        family = k % 5
        pair = []
        for _ in range(2):
            if family == 0:    # bright
                c = rng.uniform(-1.0, 4.5, 3)
            elif family == 1:  # near white
                c = rng.uniform(0.9, 4.2) + rng.uniform(-0.05, 0.05, 3)
            elif family == 2:  # near black
                c = rng.uniform(-0.002, 0.004, 3)
            elif family == 3:  # saturated: a primary or secondary, scaled and pushed out
                corner = np.eye(3)[rng.integers(3)]
                if rng.integers(2):
                    corner = 1.0 - corner
                c = corner * rng.uniform(0.2, 2.0) + rng.uniform(-0.3, 0.1, 3)
            else:              # HDR
                c = rng.uniform(-5.0, 100.0, 3)
            pair.append(c * peak)
        ends.append(pair)
    return np.array(ends)


def difference(a, b, space, peak):
    """ΔE2000 of outputs relative to the white (peak, peak, peak)."""
    lab_a = irid.convert(np.asarray(a, np.float64) / peak, space, "lab")
    lab_b = irid.convert(np.asarray(b, np.float64) / peak, space, "lab")
    return irid.delta_e(lab_a, lab_b)


def allowed(method, space, peak, a, b, out_a, out_b):
    """A jump between the colours a and b is forced by the definition where they take different
    branches of it (irid.clip_branches; GAMUT.md, "Where a method may jump"). luv-hue's, checked
    more strictly as in the C++ walk: CIELUV's chromaticity undefined on one side
    (X + 15Y + 3Z <= 0), or a tie between two nearest points (the same ΔE*uv from the colour)."""
    params = {"clip": True} if method == "aces-rgc" else {}
    sig = irid.clip_branches(np.array([a, b]), method, source=space, max=peak, **params)
    if sig[0] == sig[1]:
        return False
    if method in ("oklab", "oklab-adaptive"):
        # Both outputs on the colour's own segment toward the neutral axis: its Oklab hue, and
        # one line through it in the (L, C) plane (a choice between two pieces of it).
        lab = irid.convert(np.array([a, out_a, out_b]) / peak, space, "oklab")
        c = np.hypot(lab[:, 1], lab[:, 2])
        h = np.arctan2(lab[:, 2], lab[:, 1])
        tol = 1e-6
        dh = np.abs((h[1:] - h[0] + np.pi) % (2 * np.pi) - np.pi)
        if np.any((c[1:] > tol) & (dh > 1e-5)):
            return False
        l1, c1, l2, c2 = lab[1, 0] - lab[0, 0], c[1] - c[0], lab[2, 0] - lab[0, 0], c[2] - c[0]
        return bool(abs(l1 * c2 - l2 * c1) <= tol * (np.hypot(l1, c1) + np.hypot(l2, c2) + tol))
    if method != "luv-hue":
        return True
    xyz = irid.convert(np.array([a, b]) / peak, space, "xyz")
    undefined = xyz[:, 0] + 15.0 * xyz[:, 1] + 3.0 * xyz[:, 2] <= 0.0
    if undefined[0] != undefined[1]:
        return True
    luv_in = irid.convert(np.array([a, b]) / peak, space, "luv")
    luv_out = irid.convert(np.array([out_a, out_b]) / peak, space, "luv")
    da, db = irid.delta_e(luv_in, luv_out, metric="cieuv")
    return bool(abs(da - db) <= 1e-4 * max(1.0, da))


def clip(points, method, space, peak, dtype):
    params = {"clip": True} if method == "aces-rgc" else {}
    out = irid.clip(np.ascontiguousarray(points, dtype=dtype), method, source=space, max=peak,
                    threads=1, **params)
    return out.astype(np.float64)


@pytest.mark.parametrize("method", irid.clip_methods())
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_jumps_only_where_the_definition_forces_them(method, dtype):
    rng = np.random.default_rng(23)
    for space, peak in (("srgb-linear", 1.0), ("rec2020-linear", 100.0)):
        ends = segments(rng, 40, peak)
        t = np.linspace(0.0, 1.0, STEPS + 1)
        points = ends[:, :1, :] + t[None, :, None] * (ends[:, 1:, :] - ends[:, :1, :])
        if dtype == np.float32:
            # Bisect on what the kernels see: the float32 colours.
            points = points.astype(np.float32).astype(np.float64)
        out = clip(points.reshape(-1, 3), method, space, peak, dtype).reshape(points.shape)
        step = difference(out[:, :-1], out[:, 1:], space, peak)
        seg, k = np.nonzero(step > 2.0)
        a, b = points[seg, k], points[seg, k + 1]
        oa, ob = out[seg, k], out[seg, k + 1]
        for _ in range(60):
            if len(a) == 0:
                break
            m = 0.5 * (a + b)
            if dtype == np.float32:
                m = m.astype(np.float32).astype(np.float64)
            om = clip(m, method, space, peak, dtype)
            left = difference(oa, om, space, peak) >= difference(om, ob, space, peak)
            b = np.where(left[:, None], m, b)
            ob = np.where(left[:, None], om, ob)
            a = np.where(left[:, None], a, m)
            oa = np.where(left[:, None], oa, om)
            if np.all(np.max(np.abs(b - a), axis=1) <= 1e-10 * peak):
                break
        jumps = difference(oa, ob, space, peak) > 1.0
        for i in np.nonzero(jumps)[0]:
            assert allowed(method, space, peak, a[i], b[i], oa[i], ob[i]), (
                f"{method} on {space} at peak {peak} jumps by ΔE2000 "
                f"{difference(oa[i], ob[i], space, peak):.3g} between {a[i].tolist()} → "
                f"{oa[i].tolist()} and {b[i].tolist()} → {ob[i].tolist()}")


def test_branches_are_zero_inside_and_for_methods_without_branches():
    inside = np.array([[0.2, 0.5, 0.7], [1.0, 0.0, 0.0]])
    assert irid.clip_branches(inside, "css").tolist() == [0, 0]
    outside = np.array([[1.5, -0.2, 0.3], [2.0, 1.9, 1.8]])
    assert irid.clip_branches(outside, "smits").tolist() == [0, 0]
    sig = irid.clip_branches(outside, "css")
    assert sig.dtype == np.uint64 and sig.shape == (2,) and np.all(sig != 0)
    # The colour above the white's lightness takes CSS's white rule, the other the search.
    assert sig[0] != sig[1]
    with pytest.raises(KeyError):
        irid.clip_branches(outside, "no-such-method")
    with pytest.raises(ValueError):
        irid.clip_branches(np.zeros((2, 2)), "css")

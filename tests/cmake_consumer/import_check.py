"""The installed Python package imports from the install prefix and works (run.cmake)."""
import sys

site = sys.argv[1]
import irid  # noqa: E402
import numpy  # noqa: E402

assert irid.__file__.startswith(site), (irid.__file__, site)
r = irid.clip(numpy.array([2.0, 0.5, 0.5]), "smits")
assert abs(r.max() - 1.0) < 1e-12, r
pixels, meta = irid.read_image(sys.argv[2])   # the OpenImageIO module installed beside it
assert pixels.ndim == 3 and meta["channels"][:3] == ["R", "G", "B"], meta
print("installed irid imports from", irid.__file__)

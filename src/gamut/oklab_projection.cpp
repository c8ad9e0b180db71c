#include <irid/gamut/clip.h>

namespace irid {

void GamutClipper::prepare_oklab_projection() {}  // PROVISIONAL

Rgb GamutClipper::oklab_adaptive(const Rgb& c) const noexcept { return oklab(c); }  // PROVISIONAL
Rgb GamutClipper::oklab_cusp(const Rgb& c) const noexcept { return oklab(c); }  // PROVISIONAL

}  // namespace irid

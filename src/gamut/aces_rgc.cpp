#include <irid/gamut/clip.h>

namespace irid {

void GamutClipper::prepare_aces_rgc() {}  // PROVISIONAL

Rgb GamutClipper::aces_rgc(const Rgb& c) const noexcept { return c; }  // PROVISIONAL

}  // namespace irid

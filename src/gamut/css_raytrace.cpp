#include <irid/gamut/clip.h>

namespace irid {

Rgb GamutClipper::css_raytrace(const Rgb& c) const noexcept { return css(c); }  // PROVISIONAL

}  // namespace irid

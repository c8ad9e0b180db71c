#include <irid/gamut/clip.h>

namespace irid {

void GamutClipper::prepare_smits_soft() {}  // PROVISIONAL

Rgb GamutClipper::smits_soft(const Rgb& c) const noexcept { return smits(c); }  // PROVISIONAL

}  // namespace irid

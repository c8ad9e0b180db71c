#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/gamut/tone.h>

#include <string>

namespace irid {

HighlightRolloff::HighlightRolloff(double knee) : m_knee(knee), m_range(1.0 - knee) {
    if (!(knee >= 0.0 && knee <= max_knee)) {
        std::string message = "highlight roll-off: knee is ";
        message += format_shortest(knee);
        message += "; allowed: [0, ";
        message += format_shortest(max_knee);
        message += "]";
        throw Error(message);
    }
}

}  // namespace irid

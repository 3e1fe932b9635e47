#include "railodd/xodr/model.hpp"

#include <stdexcept>

namespace railodd::xodr {

Revision parse_revision(const std::string& text) {
    if (text == "1.6") {
        return Revision::v1_6;
    }
    if (text == "1.7") {
        return Revision::v1_7;
    }
    if (text == "1.8") {
        return Revision::v1_8;
    }
    throw std::invalid_argument("OpenDRIVE revision '" + text + "' is not supported (1.6, 1.7 or 1.8)");
}

const char* to_string(Revision revision) {
    switch (revision) {
    case Revision::v1_6:
        return "1.6";
    case Revision::v1_7:
        return "1.7";
    case Revision::v1_8:
        return "1.8";
    }
    return "?";
}

double Road::length() const {
    double total = 0.0;
    for (const auto& g : plan_view) {
        total += g.length;
    }
    return total;
}

} // namespace railodd::xodr

#include "bins.hpp"

#include "text.hpp"

#include <cmath>
#include <set>

namespace railodd::odd {

bool Bin::contains(double value) const {
    const bool above = lower_closed ? value >= lower : value > lower;
    const bool below = upper_closed ? value <= upper : value < upper;
    return above && below;
}

namespace {

std::string bound_text(double v) {
    if (std::isinf(v)) {
        return v < 0 ? "-inf" : "inf";
    }
    return text::format(v);
}

// A bound: a strict number or (-)inf; "+inf" and "-inf" only where they make sense.
bool parse_bound(std::string_view s, double& out) {
    s = text::trim(s);
    if (s == "inf" || s == "+inf") {
        out = std::numeric_limits<double>::infinity();
        return true;
    }
    if (s == "-inf") {
        out = -std::numeric_limits<double>::infinity();
        return true;
    }
    const auto n = text::strict_number(s);
    if (!n) {
        return false;
    }
    out = *n;
    return true;
}

} // namespace

std::string Bin::interval() const {
    return std::string(lower_closed ? "[" : "(") + bound_text(lower) + ", " + bound_text(upper) +
           (upper_closed ? "]" : ")");
}

namespace bins {

std::string parse_range(std::string_view range, Bin& bin) {
    const auto t = text::trim(range);
    const auto expected = "range '" + std::string(range) + "' is not an interval like \"[0, 300)\" or \"(40, inf)\"";
    if (t.size() < 5 || (t.front() != '[' && t.front() != '(') || (t.back() != ']' && t.back() != ')')) {
        return expected;
    }
    const auto parts = text::split(t.substr(1, t.size() - 2), ',');
    if (parts.size() != 2 || !parse_bound(parts[0], bin.lower) || !parse_bound(parts[1], bin.upper)) {
        return expected;
    }
    bin.lower_closed = t.front() == '[';
    bin.upper_closed = t.back() == ']';
    if ((std::isinf(bin.lower) && bin.lower > 0) || (std::isinf(bin.upper) && bin.upper < 0)) {
        return "range '" + std::string(range) + "' has an infinite bound on the wrong side";
    }
    // An infinite end is never reached, so it is open whatever bracket was written.
    if (std::isinf(bin.lower)) {
        bin.lower_closed = false;
    }
    if (std::isinf(bin.upper)) {
        bin.upper_closed = false;
    }
    const bool empty = bin.lower > bin.upper ||
                       (bin.lower == bin.upper && !(bin.lower_closed && bin.upper_closed));
    if (empty) {
        return "range '" + std::string(range) + "' is empty (lower bound not below upper bound)";
    }
    return {};
}

std::string check_sequence(const std::vector<Bin>& bins) {
    std::set<std::string> labels;
    for (std::size_t i = 0; i < bins.size(); ++i) {
        const Bin& b = bins[i];
        if (!labels.insert(b.label).second) {
            return "bin label '" + b.label + "' is used twice";
        }
        if (i == 0) {
            continue;
        }
        const Bin& a = bins[i - 1];
        const auto pair = "bins '" + a.label + "' " + a.interval() + " and '" + b.label + "' " + b.interval();
        if (b.lower < a.lower || (b.lower == a.lower && b.upper < a.upper)) {
            return pair + " are not in ascending order";
        }
        if (b.lower < a.upper || (b.lower == a.upper && a.upper_closed && b.lower_closed)) {
            return pair + " overlap";
        }
        if (b.lower > a.upper || (b.lower == a.upper && !a.upper_closed && !b.lower_closed)) {
            return pair + " leave a gap (bins must tile their range)";
        }
    }
    return {};
}

} // namespace bins

std::string classify(const Attribute& attribute, double value) {
    for (const Bin& b : attribute.bins) {
        if (b.contains(value)) {
            return b.label;
        }
    }
    return {};
}

} // namespace railodd::odd

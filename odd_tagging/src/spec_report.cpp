// The verdict of check_spec() as terminal text and as JSON (spec_check.hpp).
#include "railodd/odd/spec_check.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace railodd::odd {

namespace {

using ojson = nlohmann::ordered_json;

std::string printf_text(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printf_text(const char* format, ...) {
    char buf[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buf, sizeof buf, format, args);
    va_end(args);
    return buf;
}

std::string joined(const std::vector<std::string>& parts, const char* sep) {
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        s += (i > 0 ? sep : "") + parts[i];
    }
    return s;
}

std::string range_text(double a, double b, bool point) {
    return point ? printf_text("%.1f", a) : printf_text("%.1f-%.1f", a, b);
}

// One line per violation: where (track, chainage, road and s), what, and the
// OSM objects behind it, so that a reader can look the place up directly.
std::string violation_line(const SpecViolation& v) {
    std::string what = v.element + ": ";
    if (v.attribute.empty()) {
        what += v.constraint;
    } else {
        what += v.attribute + " " + v.value + (v.unit.empty() ? "" : " " + v.unit) + ", spec " + v.constraint;
    }
    if (v.spec_line > 0) {
        what += printf_text(" (spec line %d)", v.spec_line);
    }
    std::string line = printf_text("  track %zu ch %s m  road %s s %s  ", v.track,
                                   range_text(v.chainage_start, v.chainage_end, v.point).c_str(), v.road_id.c_str(),
                                   range_text(v.s_start, v.s_end, v.point).c_str());
    line += what;
    if (!v.osm_ids.empty()) {
        line += "  osm " + joined(v.osm_ids, " ");
    }
    return line + "\n";
}

ojson violation_json(const SpecViolation& v) {
    ojson j;
    j["element"] = v.element;
    j["spec_element"] = v.spec_element;
    j["attribute"] = v.attribute;
    j["value"] = v.value;
    j["unit"] = v.unit;
    j["constraint"] = v.constraint;
    j["note"] = v.note;
    j.update(ojson(static_cast<const MapPlace&>(v)));
    j["spec_line"] = v.spec_line;
    return j;
}

std::string stretches_text(const SpecVerdict& verdict) {
    if (verdict.stretches.empty()) {
        return "";
    }
    std::string out = printf_text("stretches outside the ODD: %zu\n", verdict.stretches.size());
    for (const auto& s : verdict.stretches) {
        const bool point = s.chainage_end - s.chainage_start < 1e-3;
        const std::string where = range_text(s.chainage_start, s.chainage_end, point) + " m" +
                                  (point ? "" : printf_text(" (%.1f m)", s.chainage_end - s.chainage_start));
        out += printf_text("  track %zu ch %s  roads %s  %zu violation%s: ", s.track, where.c_str(),
                           joined(s.road_ids, " ").c_str(), s.violations, s.violations == 1 ? "" : "s");
        out += joined(s.elements, ", ") + "\n";
    }
    return out;
}

std::string entries_text(const SpecVerdict& verdict) {
    std::size_t width = 10;
    for (const auto& c : verdict.entries) {
        width = std::max(width, c.path.size());
    }
    std::string out = printf_text("%-*s %5s %8s %8s %8s\n", static_cast<int>(width + 2), "spec entry", "line",
                                  "matched", "outside", "unknown");
    for (const auto& c : verdict.entries) {
        out += printf_text("  %-*s %5d %8zu %8zu %8zu", static_cast<int>(width), c.path.c_str(), c.line, c.matched,
                           c.outside, c.unknown);
        if (!c.unknown_attributes.empty()) {
            out += "  (missing: " + joined(c.unknown_attributes, ", ") + ")";
        }
        out += "\n";
    }
    out += printf_text("  %-*s %5s %8zu\n", static_cast<int>(width), "(not listed)", "", verdict.elements_unlisted);
    return out;
}

} // namespace

std::string verdict_text(const SpecVerdict& verdict, std::size_t max_violations) {
    std::string out = "ODD spec: " + verdict.spec_name + " (" + verdict.spec_source + ")\n";
    out += printf_text("verdict: %s  (%zu of %zu elements outside, %zu violations)\n",
                       verdict.passed ? "IN ODD" : "OUTSIDE ODD", verdict.elements_outside, verdict.elements_checked,
                       verdict.violations.size());
    if (!verdict.violations.empty()) {
        out += "violations:\n";
        for (std::size_t i = 0; i < verdict.violations.size() && i < max_violations; ++i) {
            out += violation_line(verdict.violations[i]);
        }
        if (verdict.violations.size() > max_violations) {
            out += printf_text("  ... %zu more\n", verdict.violations.size() - max_violations);
        }
    }
    out += stretches_text(verdict);
    out += entries_text(verdict);
    return out;
}

nlohmann::ordered_json verdict_json(const SpecVerdict& verdict) {
    ojson j;
    j["spec"] = {{"name", verdict.spec_name}, {"file", verdict.spec_source}};
    j["passed"] = verdict.passed;
    j["verdict"] = verdict.passed ? "IN ODD" : "OUTSIDE ODD";
    j["elements_checked"] = verdict.elements_checked;
    j["elements_outside"] = verdict.elements_outside;
    j["elements_unlisted"] = verdict.elements_unlisted;
    ojson violations = ojson::array();
    for (const auto& v : verdict.violations) {
        violations.push_back(violation_json(v));
    }
    j["violations"] = std::move(violations);
    ojson stretches = ojson::array();
    for (const auto& s : verdict.stretches) {
        stretches.push_back({{"track", s.track},
                             {"chainage_start", s.chainage_start},
                             {"chainage_end", s.chainage_end},
                             {"road_ids", s.road_ids},
                             {"elements", s.elements},
                             {"violations", s.violations}});
    }
    j["stretches_outside"] = std::move(stretches);
    ojson entries = ojson::array();
    for (const auto& c : verdict.entries) {
        entries.push_back({{"path", c.path},
                           {"line", c.line},
                           {"matched", c.matched},
                           {"outside", c.outside},
                           {"unknown", c.unknown},
                           {"unknown_attributes", c.unknown_attributes}});
    }
    j["entries"] = std::move(entries);
    return j;
}

} // namespace railodd::odd

// The verdict of `railodd validate`, as text for people and as JSON for
// scripts. Both list the same figures in the same order.
#include "railodd/xodr_check/check.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace railodd::xodr_check {

bool Verdict::passed() const {
    return checks && checks->passed() && (!schema || schema->valid) && (!netconvert || netconvert->passed());
}

namespace {

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string worst_line(const char* label, const Worst& w, double limit, const char* unit) {
    const std::string u = *unit ? std::string{" "} + unit : std::string{}; // grades have no unit
    std::string line = std::string{"  "} + label + fmt("%.3g", w.value) + u + " (limit " + fmt("%g", limit) + u + ")";
    if (!w.where.empty()) {
        line += " at " + w.where;
    }
    return line + (w.value > limit ? "  EXCEEDED\n" : "\n");
}

std::string finding_line(const Finding& f) {
    std::string where = f.object + " " + f.id;
    if (!std::isnan(f.s)) {
        where += fmt(" s=%.3f", f.s);
    }
    return std::string{"    "} + (f.severity == Severity::error ? "error  " : "warning") + "  " + where + "  " + f.check +
           ": " + f.message + "\n";
}

void schema_text(std::ostringstream& o, const SchemaResult& s) {
    o << "  schema: " << (s.valid ? "valid" : "INVALID") << " against " << s.xsd << '\n';
    if (!s.valid) {
        o << "    " << s.error_count << " error line(s) from " << s.validator << ", first:\n";
        for (const auto& e : s.errors) {
            o << "      " << e << '\n';
        }
    }
}

void netconvert_text(std::ostringstream& o, const NetconvertResult& n) {
    o << "  netconvert: " << (n.passed() ? "ok" : "FAILED") << " (exit " << n.exit_code << "), " << n.edges
      << " edges, " << n.rail_edges << " allowing rail or tram\n";
    for (const auto& e : n.errors) {
        o << "    " << e << '\n';
    }
}

nlohmann::ordered_json worst_json(const Worst& w, double limit) {
    return {{"value", w.value}, {"limit", limit}, {"where", w.where}};
}

nlohmann::ordered_json summary_json(const Summary& s, const Limits& l) {
    nlohmann::ordered_json j;
    j["version"] = s.version;
    j["roads"] = s.roads;
    j["rail_roads"] = s.rail_roads;
    j["geometries_by_kind"] = s.geometries_by_kind;
    j["junctions"] = s.junctions;
    j["connections"] = s.connections;
    j["switches"] = s.switches;
    j["stations"] = s.stations;
    j["links_checked"] = s.links_checked;
    j["short_records"] = s.short_records;
    j["shortest_record"] = {{"value", std::isfinite(s.shortest_record_m) ? s.shortest_record_m : 0.0},
                            {"where", s.shortest_record_at}};
    j["max_gap_m"] = worst_json(s.gap_m, l.gap_m);
    j["max_heading_jump_rad"] = worst_json(s.heading_jump_rad, l.heading_rad);
    j["max_rail_curvature_jump_per_m"] = worst_json(s.rail_curvature_jump, l.rail_curvature_per_m);
    j["max_elevation_gap_m"] = worst_json(s.elevation_gap_m, l.elevation_gap_m);
    j["max_link_height_m"] = worst_json(s.link_height_m, l.link_height_m);
    j["max_link_grade"] = worst_json(s.link_grade, l.link_grade);
    return j;
}

nlohmann::ordered_json finding_json(const Finding& f) {
    nlohmann::ordered_json j;
    j["severity"] = f.severity == Severity::error ? "error" : "warning";
    j["object"] = f.object;
    j["id"] = f.id;
    j["s"] = std::isnan(f.s) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(f.s);
    j["check"] = f.check;
    j["message"] = f.message;
    return j;
}

} // namespace

std::string verdict_text(const Verdict& v, std::size_t max_findings) {
    const CheckResult& c = *v.checks;
    const Summary& s = c.summary;
    std::ostringstream o;
    o << "railodd validate: " << c.file << " (OpenDRIVE " << s.version << ")\n";
    o << "  roads: " << s.roads << " (" << s.rail_roads << " rail), junctions: " << s.junctions << " ("
      << s.connections << " connections), switches: " << s.switches << ", stations: " << s.stations << '\n';
    o << "  geometries:";
    for (const auto& [kind, n] : s.geometries_by_kind) {
        o << ' ' << kind << ' ' << n;
    }
    o << "\n  links checked: " << s.links_checked << '\n';
    if (std::isfinite(s.shortest_record_m)) {
        o << "  shortest record:         " << s.shortest_record_m << " m at " << s.shortest_record_at << " ("
          << s.short_records << " under 1 cm)\n";
    }
    o << worst_line("max gap:                 ", s.gap_m, v.limits.gap_m, "m");
    o << worst_line("max heading jump:        ", s.heading_jump_rad, v.limits.heading_rad, "rad");
    o << worst_line("max rail curvature jump: ", s.rail_curvature_jump, v.limits.rail_curvature_per_m, "1/m");
    o << worst_line("max elevation gap:       ", s.elevation_gap_m, v.limits.elevation_gap_m, "m");
    o << worst_line("max link height step:    ", s.link_height_m, v.limits.link_height_m, "m");
    o << worst_line("max link grade change:   ", s.link_grade, v.limits.link_grade, "");
    o << "  checks: " << c.errors() << " error(s), " << c.warnings() << " warning(s)\n";
    if (v.schema) {
        schema_text(o, *v.schema);
    }
    if (v.netconvert) {
        netconvert_text(o, *v.netconvert);
    }
    if (!c.findings.empty()) {
        const std::size_t n = std::min(max_findings, c.findings.size());
        o << "  findings (first " << n << " of " << c.findings.size() << "):\n";
        for (std::size_t i = 0; i < n; ++i) {
            o << finding_line(c.findings[i]);
        }
    }
    o << (v.passed() ? "PASS" : "FAIL") << '\n';
    return o.str();
}

std::string verdict_json(const Verdict& v) {
    const CheckResult& c = *v.checks;
    nlohmann::ordered_json j;
    j["file"] = c.file;
    j["passed"] = v.passed();
    j["errors"] = c.errors();
    j["warnings"] = c.warnings();
    j["summary"] = summary_json(c.summary, v.limits);
    j["findings"] = nlohmann::ordered_json::array();
    for (const auto& f : c.findings) {
        j["findings"].push_back(finding_json(f));
    }
    if (v.schema) {
        j["schema"] = {{"valid", v.schema->valid}, {"xsd", v.schema->xsd}, {"validator", v.schema->validator},
                       {"error_count", v.schema->error_count}, {"errors", v.schema->errors}};
    }
    if (v.netconvert) {
        j["netconvert"] = {{"passed", v.netconvert->passed()}, {"exit_code", v.netconvert->exit_code},
                           {"errors", v.netconvert->errors}, {"edges", v.netconvert->edges},
                           {"rail_edges", v.netconvert->rail_edges}};
    }
    return j.dump(2) + "\n";
}

} // namespace railodd::xodr_check

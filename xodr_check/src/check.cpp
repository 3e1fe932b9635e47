// Entry points: read the document, evaluate every road's end poses once, run
// the check passes in a fixed order, and order the findings errors first.
#include "checks.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/xml_text.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

namespace railodd::xodr_check {

std::size_t CheckResult::errors() const {
    return static_cast<std::size_t>(std::count_if(findings.begin(), findings.end(),
                                                  [](const Finding& f) { return f.severity == Severity::error; }));
}

std::size_t CheckResult::warnings() const { return findings.size() - errors(); }

namespace {

void evaluate_road_ends(Document& doc) {
    for (Road& road : doc.roads) {
        if (road.geometries.empty()) {
            continue;
        }
        road.has_geometry = true;
        road.start = evaluate(road.geometries.front(), 0.0);
        const GeometryRecord& last = road.geometries.back();
        road.end = evaluate(last, last.length);
    }
}

void count_roads(const Document& doc, Summary& sum) {
    sum.version = std::to_string(doc.rev_major) + "." + std::to_string(doc.rev_minor);
    sum.roads = doc.roads.size();
    sum.rail_roads = static_cast<std::size_t>(
        std::count_if(doc.roads.begin(), doc.roads.end(), [](const Road& r) { return r.rail; }));
}

// XML 1.0 in UTF-8 (what OpenDRIVE requires): pugixml reads control
// characters and invalid byte sequences without complaint, strict readers
// (libxml2, SUMO's Xerces) refuse the whole file.
void check_encoding(const std::string& xml, const std::string& name, CheckResult& result) {
    const std::size_t at = first_non_xml_text(xml);
    if (at == std::string::npos) {
        return;
    }
    const auto line = 1 + std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(xml[at]));
    result.findings.push_back({Severity::error, "file", name, nan, "encoding",
                               "byte " + std::to_string(at) + " (line " + std::to_string(line) + ", " + byte +
                                   ") is not UTF-8 XML 1.0 text (a control character or invalid UTF-8): strict "
                                   "XML readers refuse the file"});
}

} // namespace

CheckResult check_text(const std::string& xml, const std::string& name, const Limits& limits) {
    Document doc = read_document(xml, name);
    evaluate_road_ends(doc);
    CheckResult result;
    result.file = name;
    result.findings = doc.findings;
    count_roads(doc, result.summary);
    if (doc.rev_major != 1 || doc.rev_minor < 0 || doc.rev_minor > 8) {
        result.findings.push_back({Severity::error, "file", name, nan, "version",
                                   "OpenDRIVE " + result.summary.version +
                                       " does not exist (revisions 1.0 to 1.8 do): no reader can take the map"});
    } else if (doc.rev_minor < 6) {
        result.findings.push_back({Severity::warning, "file", name, nan, "version",
                                   "OpenDRIVE " + result.summary.version +
                                       ": the checks follow 1.6 to 1.8 and may not fit this revision"});
    }
    check_encoding(xml, name, result);
    Context ctx(doc, limits, result);
    check_plan_views(ctx);
    check_elevations(ctx);
    check_road_links(ctx);
    check_contact_points(ctx);
    check_elevation_links(ctx);
    check_junctions(ctx);
    check_duplicate_connections(ctx);
    check_id_collisions(ctx);
    check_rail_extensions(ctx);
    // Errors first so a truncated listing shows what failed; stable keeps the
    // document order within each severity.
    std::stable_sort(result.findings.begin(), result.findings.end(), [](const Finding& a, const Finding& b) {
        return a.severity == Severity::error && b.severity != Severity::error;
    });
    return result;
}

CheckResult check_file(const std::filesystem::path& file, const Limits& limits) {
    return check_text(read_input_file(file, "OpenDRIVE map"), file.string(), limits);
}

} // namespace railodd::xodr_check

#pragma once
// report.json's "topology" section: road-rail and track-track crossings, and
// which railway features were placed on which track (or why not).
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/feature_attachment.hpp"

#include <nlohmann/json.hpp>

namespace railodd::geometry {

nlohmann::ordered_json topology_report(const Crossings& crossings, const Attachment& attachment,
                                       const std::vector<ingest::Feature>& features);

} // namespace railodd::geometry

#pragma once
// convert's last phases: the ODD profile tagged and every output staged
// (pipeline.cpp runs the phases before them).
#include "railodd/convert/options.hpp"

#include "railodd/geometry/fitted_map.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/route.hpp"
#include "railodd/report/report.hpp"
#include "railodd/util/output_stage.hpp"
#include "railodd/util/phase_timer.hpp"
#include "railodd/xodr/map_builder.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace railodd::convert {

// What the profile left for report.json and report.html.
struct Profiled {
    // The whole profile; when it was streamed (`section` set), its head and
    // tail only: route, summary, track ends, unparsed.
    odd::OddProfile profile;
    std::optional<odd::Route> route; // --from/--to or --relation
    std::unique_ptr<report::ProfileSection> section; // the page's elements, when streamed
};

// Tags the network and stages odd_profile.*, map.xodr and the debug outputs
// (phases odd_tagging and write_outputs). A whole network's profile is
// tagged a batch of tracks at a time straight into its files and the page's
// section, while map.xodr is written on a second thread; a route's
// (--from/--to, --relation) or one carried into map.xodr (--odd-user-data)
// is made whole first.
Profiled profile_and_write(OutputStage& stage, const Options& o, const ingest::IngestResult& r, geometry::FittedMap& geo,
                           const xodr::MapInput& map_input, const xodr::MapBuild& map, xodr::Revision revision,
                           PhaseTimer& timer);

// report.html from the map, profile, report and mapped tracks in memory: the
// page is staged and committed with the files it shows. Its time is the
// phase report_html of result.timings.
void write_page(OutputStage& stage, const std::string& outdir, Profiled& profiled,
                const nlohmann::ordered_json& report, const xodr::Map& map, ingest::IngestResult& result);

} // namespace railodd::convert

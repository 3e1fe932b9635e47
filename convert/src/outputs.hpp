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

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace railodd::convert {

// What the profile left for report.json and report.html.
struct Profiled {
    odd::OddProfile profile; // its head and tail only: route, summary, track ends, unparsed
    std::optional<odd::Route> route; // --from/--to or --relation
    std::unique_ptr<report::ProfileSection> section; // the page's elements (unless --no-report)
};

// Tags the network and stages odd_profile.*, map.xodr and the debug outputs
// (phases odd_tagging and write_outputs), all fed as the network is tagged a
// batch of tracks at a time (output_sinks.hpp); map.xodr and the debug files
// are written beside the tagging. Along a route (--from/--to, --relation)
// the network's profile is collected whole and the profile's outputs are
// fed the route's, cut from it.
Profiled profile_and_write(OutputStage& stage, const Options& o, const ingest::IngestResult& r, geometry::FittedMap& geo,
                           const xodr::MapInput& map_input, const xodr::MapBuild& map, xodr::Revision revision,
                           PhaseTimer& timer);

// A second thread's work runs beside this one's, or (--threads 1) when asked for.
std::launch beside(const Options& o);

// report.html from the map, profile, report and mapped tracks in memory: the
// page is staged and committed with the files it shows. Its time is the
// phase report_html of result.timings.
void write_page(OutputStage& stage, const Options& o, Profiled& profiled,
                const nlohmann::ordered_json& report, const xodr::Map& map, ingest::IngestResult& result);

} // namespace railodd::convert

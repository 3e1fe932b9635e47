// The outputs that read the map only: map.xodr (MapOutput; with
// --odd-user-data it follows the profile too) and the debug GeoJSON files
// (DebugOutput).
#include "output_sinks.hpp"

#include "railodd/geometry/dump.hpp"
#include "railodd/ingest/dump.hpp"
#include "railodd/xodr/xml_writer.hpp"

namespace railodd::convert {

MapOutput::MapOutput(OutputStage& stage, const xodr::Map& map, xodr::Revision revision, bool odd_user_data,
                     std::launch launch)
    : stage_(stage), map_(map), revision_(revision), launch_(launch) {
    if (odd_user_data) {
        user_data_.emplace();
    }
}

void MapOutput::write(const xodr::ExtraUserData& user_data) {
    stage_.write_with("map.xodr", [&](std::ostream& out) { xodr::write_xodr(map_, revision_, out, user_data); });
}

// Without user data the map is all there is to write: beside the tagging.
void MapOutput::begin(const odd::OddProfile&) {
    if (!user_data_) {
        written_ = std::async(launch_, [this] { write({}); });
    }
}

void MapOutput::add(std::deque<odd::TaggedElement>& batch) {
    if (user_data_) {
        for (const auto& e : batch) {
            user_data_->add(e);
        }
    }
}

void MapOutput::end(const odd::OddProfile&) {
    if (user_data_) {
        const odd::OddUserData& entries = *user_data_;
        write([&entries](const xodr::Road& road) { return entries(road); });
    } else {
        written_.get();
    }
}

DebugOutput::DebugOutput(OutputStage& stage, bool wanted, const ingest::IngestResult& result,
                         const geometry::FittedMap& geo, std::launch launch)
    : stage_(stage), wanted_(wanted), result_(result), geo_(geo), launch_(launch) {}

void DebugOutput::begin(const odd::OddProfile&) {
    if (!wanted_) {
        for (const char* name : {"ingest.geojson", "geometry.geojson", "roads.geojson"}) {
            stage_.remove_on_commit(name);
        }
        return;
    }
    written_ = std::async(launch_, [this] {
        stage_.write_with("ingest.geojson", [&](std::ostream& out) { ingest::write_geojson(result_, out); });
        stage_.write_with("geometry.geojson", [&](std::ostream& out) {
            geometry::write_geojson(geo_.tracks, geo_.fitted_tracks, result_.projection, "track", out);
        });
        stage_.write_with("roads.geojson", [&](std::ostream& out) {
            geometry::write_geojson(geo_.roads, geo_.fitted_roads, result_.projection, "road", out);
        });
    });
}

void DebugOutput::end(const odd::OddProfile&) {
    if (written_.valid()) {
        written_.get();
    }
}

} // namespace railodd::convert

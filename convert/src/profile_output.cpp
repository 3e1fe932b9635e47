// The outputs that follow the profile: its three files (ProfileFilesOutput)
// and the page's share of it (PageSectionOutput); Outputs feeds several.
#include "output_sinks.hpp"

namespace railodd::convert {

void Outputs::begin(const odd::OddProfile& head) {
    for (auto& o : outputs_) {
        o->begin(head);
    }
}

void Outputs::add(std::deque<odd::TaggedElement>& batch) {
    for (auto& o : outputs_) {
        o->add(batch);
    }
}

void Outputs::end(const odd::OddProfile& tail) {
    for (auto& o : outputs_) {
        o->end(tail);
    }
}

ProfileFilesOutput::ProfileFilesOutput(OutputStage& stage, bool own_thread)
    : json_(stage, "odd_profile.json"), geojson_(stage, "odd_profile.geojson"), csv_(stage, "odd_profile.csv"),
      files_(json_.stream(), geojson_.stream(), csv_.stream(), stage.scratch_path("odd_profile.rows")) {
    if (own_thread) {
        thread_.emplace(files_);
    }
}

void ProfileFilesOutput::end(const odd::OddProfile& tail) {
    sink().end(tail);
    json_.close();
    geojson_.close();
    csv_.close();
}

void PageSectionOutput::begin(const odd::OddProfile& head) {
    if (page_map_) {
        std::vector<std::string> road_ids;
        for (const auto& road : page_map_->roads) {
            road_ids.push_back(road.id);
        }
        out_.section = std::make_unique<report::ProfileSection>(head, road_ids);
    }
}

void PageSectionOutput::add(std::deque<odd::TaggedElement>& batch) {
    if (out_.section) {
        for (const auto& e : batch) {
            out_.section->add(e);
        }
    }
}

} // namespace railodd::convert

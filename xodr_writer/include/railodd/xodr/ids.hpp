#pragma once
// Deterministic OpenDRIVE ids: handed out in the order the builders visit the
// (deterministically ordered) graph, so the same input gives the same ids.
#include <string>

namespace railodd::xodr {

class IdCounter {
public:
    std::string road() { return std::to_string(next_road_++); }
    std::string junction() { return std::to_string(next_junction_++); }
    std::string signal() { return std::to_string(next_signal_++); }
    std::string object() { return std::to_string(next_object_++); }
    std::string station() { return std::to_string(next_station_++); }
    std::string other() { return std::to_string(next_other_++); } // switches, platforms, connections

private:
    long next_road_ = 1;
    long next_junction_ = 1;
    long next_signal_ = 1;
    long next_object_ = 1;
    long next_station_ = 1;
    long next_other_ = 1;
};

} // namespace railodd::xodr

// Reading what the player wrote: the recorded trajectories (dat2csv
// --extended) and the console log's errors and warnings.
#include "railodd/scenario/play.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <string_view>

namespace railodd::scenario::play {

namespace {

std::string_view trim(std::string_view v) {
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) {
        v.remove_prefix(1);
    }
    while (!v.empty() && (v.back() == ' ' || v.back() == '\t' || v.back() == '\r')) {
        v.remove_suffix(1);
    }
    return v;
}

std::vector<std::string_view> fields(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) {
            return out;
        }
        start = comma + 1;
    }
}

// "nan" and "inf" parse as such: a NaN in a trajectory is a finding
// (analyse), not a malformed file.
bool number(std::string_view v, double& out) {
    const auto r = std::from_chars(v.data(), v.data() + v.size(), out);
    return r.ec == std::errc{} && r.ptr == v.data() + v.size();
}

// OpenDRIVE lanes are numbered outward from the centre: a few dozen at most.
constexpr double max_lane_id = 1000.0;

} // namespace

Trajectories read_trajectories(std::istream& in, const std::string& source) {
    Trajectories out;
    std::string line;
    std::size_t line_no = 0;
    std::map<std::string, std::size_t> column;
    while (std::getline(in, line)) {
        ++line_no;
        const auto f = fields(line);
        if (column.empty()) {
            for (std::size_t i = 0; i < f.size(); ++i) {
                column[std::string{f[i]}] = i;
            }
            for (const char* need : {"time", "name", "x", "y", "h", "roadId", "laneId", "offset", "s", "speed"}) {
                if (!column.count(need)) {
                    throw InputError(source, std::string{"no column '"} + need +
                                                 "' in the header (expected dat2csv --extended output)");
                }
            }
            continue;
        }
        if (trim(line).empty()) {
            continue;
        }
        auto at = [&](const char* name) { return column.at(name) < f.size() ? f[column.at(name)] : std::string_view{}; };
        Sample s;
        double lane = 0.0;
        const bool ok = number(at("time"), s.t) && number(at("x"), s.x) && number(at("y"), s.y) &&
                        number(at("h"), s.h) && number(at("laneId"), lane) && number(at("offset"), s.lane_offset) &&
                        number(at("s"), s.s) && number(at("speed"), s.speed);
        if (!ok || at("name").empty()) {
            throw InputError(source + ":" + std::to_string(line_no), "malformed trajectory row");
        }
        // Cast only what is a lane id: 1e300 or NaN into an int is undefined.
        if (!(std::abs(lane) <= max_lane_id) || lane != std::trunc(lane)) {
            throw InputError(source + ":" + std::to_string(line_no),
                             "lane id '" + std::string{at("laneId")} + "' is not a lane number");
        }
        s.lane_id = static_cast<int>(lane);
        s.road_id = std::string{at("roadId")};
        out[std::string{at("name")}].push_back(std::move(s));
    }
    if (column.empty()) {
        throw InputError(source, "empty trajectory file");
    }
    for (auto& [name, samples] : out) {
        std::stable_sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.t < b.t; });
    }
    return out;
}

PlayerLog read_player_log(std::istream& in) {
    // Errors esmini 3.6 prints for input it skips, with no effect on the run:
    // PROJ parameters of the geoReference it does not parse (the map's
    // projection is complete and standard).
    static const std::string_view ignorable[] = {"Unsupported geo reference attr"};
    PlayerLog log;
    std::set<std::string> warnings;
    std::string line;
    while (std::getline(in, line)) {
        if (line.find("[error]") != std::string::npos) {
            const bool skip = std::any_of(std::begin(ignorable), std::end(ignorable),
                                          [&](std::string_view i) { return line.find(i) != std::string::npos; });
            (skip ? log.ignorable_errors : log.errors).push_back(line);
        } else if (const auto w = line.find("[warn]"); w != std::string::npos) {
            warnings.insert(std::string{trim(std::string_view{line}.substr(w + 6))});
        }
    }
    log.warnings.assign(warnings.begin(), warnings.end());
    return log;
}

} // namespace railodd::scenario::play

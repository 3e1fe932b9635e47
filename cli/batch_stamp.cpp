#include "batch_stamp.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/json_depth.hpp"

#include <fstream>
#include <sstream>

namespace railodd::cli {

namespace fs = std::filesystem;

namespace {

// Small files (polygons, taxonomies, catalogs) by content: a checkout or copy
// that touches their time does not force a rerun. Large ones (extracts, DEM
// tiles) by size and modification time: hashing gigabytes on every re-run
// would cost more than many conversions.
constexpr std::uintmax_t content_hash_limit = 4u << 20;

nlohmann::ordered_json fingerprint(const std::string& path) {
    nlohmann::ordered_json f;
    f["path"] = path;
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) {
        f["missing"] = true;
        return f;
    }
    f["size"] = size;
    if (size <= content_hash_limit) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        f["fnv1a64"] = fnv1a_hex(s.str());
    } else {
        f["mtime_ns"] = fs::last_write_time(path, ec).time_since_epoch().count();
    }
    return f;
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

nlohmann::ordered_json make_stamp(const BatchRoute& route) {
    nlohmann::ordered_json s;
    s["railodd"] = {{"format", "batch_stamp"}, {"format_version", 1}, {"version", railodd_version}};
    s["route"] = route.spec;
    nlohmann::ordered_json files = nlohmann::ordered_json::array();
    for (const auto& f : route.files) {
        files.push_back(fingerprint(f));
    }
    s["files"] = std::move(files);
    // The version string changes rarely during development; a rebuilt
    // executable may write different outputs, so it counts too.
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    s["executable"] = {{"size", ec ? 0 : fs::file_size(exe, ec)},
                       {"mtime_ns", ec ? 0 : fs::last_write_time(exe, ec).time_since_epoch().count()}};
    s["key"] = fnv1a_hex(s.dump());
    return s;
}

bool up_to_date(const fs::path& dir, const BatchRoute& route, const nlohmann::ordered_json& stamp) {
    const fs::path file = dir / batch_stamp_name;
    if (!fs::is_regular_file(file)) {
        return false;
    }
    const std::string text = read_text(file);
    if (json_depth(text) > max_json_depth) {
        return false; // not a stamp railodd wrote: the route is built again
    }
    const auto old = nlohmann::ordered_json::parse(text, nullptr, false);
    if (old.is_discarded() || old != stamp) {
        return false;
    }
    for (const char* out : {"map.xodr", "odd_profile.json", "report.json"}) {
        if (!fs::is_regular_file(dir / out)) {
            return false;
        }
    }
    return !route.scenarios || fs::is_regular_file(dir / "scenarios" / "coverage.json");
}

void write_stamp(const fs::path& dir, const nlohmann::ordered_json& stamp) {
    const fs::path tmp = dir / (std::string{batch_stamp_name} + ".tmp");
    {
        std::ofstream out(tmp, std::ios::binary);
        out << stamp.dump(2) << '\n';
        if (!out) {
            throw OutputError(tmp.string(), "cannot write the batch stamp");
        }
    }
    fs::rename(tmp, dir / batch_stamp_name);
}

void remove_stamp(const fs::path& dir) {
    std::error_code ec;
    fs::remove(dir / batch_stamp_name, ec);
}

} // namespace railodd::cli

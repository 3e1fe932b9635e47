#include "xosc_support.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace railodd::scenario::xosc {

namespace fs = std::filesystem;

std::string num(double v) {
    if (!std::isfinite(v)) {
        throw std::domain_error("OpenSCENARIO writer: non-finite number");
    }
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6);
    std::string s(buf, r.ptr);
    if (s.find('.') != std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') {
            s.pop_back();
        }
    }
    if (s == "-0") {
        s = "0"; // a tiny negative value rounds to "-0"
    }
    return s;
}

void check_revision(const WriteOptions& opt) {
    if (opt.rev_minor < 1 || opt.rev_minor > 3) {
        throw UsageError("OpenSCENARIO 1." + std::to_string(opt.rev_minor),
                         "unsupported revision: the writer supports 1.1, 1.2 and 1.3");
    }
}

pugi::xml_node begin_document(pugi::xml_document& doc, const WriteOptions& opt, const std::string& date,
                              const std::string& description, const std::string& author) {
    check_revision(opt);
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    attr(decl, "version", "1.0");
    attr(decl, "encoding", "UTF-8");
    pugi::xml_node root = doc.append_child("OpenSCENARIO");
    pugi::xml_node header = root.append_child("FileHeader");
    attr(header, "revMajor", 1);
    attr(header, "revMinor", opt.rev_minor);
    attr(header, "date", date);
    attr(header, "description", description);
    attr(header, "author", author);
    return root;
}

std::string to_text(const pugi::xml_document& doc) {
    std::ostringstream out;
    doc.save(out, "  ", pugi::format_indent, pugi::encoding_utf8);
    return out.str();
}

void write_atomically(const fs::path& file, std::string_view text) {
    // Same directory as the target, so the rename never crosses file systems.
    std::string tmp_name{"."};
    tmp_name += file.filename().string();
    tmp_name += ".tmp-";
    tmp_name += std::to_string(::getpid());
    const fs::path tmp = file.parent_path() / tmp_name;
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw OutputError(file.string(), std::string{"cannot write: "} + std::strerror(errno));
        }
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(tmp, ignored);
            throw OutputError(file.string(), "write failed");
        }
    }
    std::error_code ec;
    fs::rename(tmp, file, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw OutputError(file.string(), "cannot move into place: " + ec.message());
    }
}

bool Context::declared(std::string_view name) const {
    return std::any_of(sc_.parameters.begin(), sc_.parameters.end(),
                       [&](const Parameter& p) { return p.name == name; });
}

std::string Context::value(std::string_view name, const std::string& literal) const {
    if (!declared(name)) {
        return literal;
    }
    std::string ref{"$"};
    ref += name;
    return ref;
}

void lane_position(pugi::xml_node parent, const LanePlacement& p, bool orientation) {
    pugi::xml_node lp = parent.append_child("LanePosition");
    attr(lp, "roadId", p.road_id);
    attr(lp, "laneId", p.lane_id);
    attr(lp, "offset", p.offset);
    attr(lp, "s", p.s);
    // Explicit, so that a tool's default (road or lane direction) never
    // decides which way the actor faces; but not on a trajectory's vertices,
    // where the path's direction is the heading (esmini 3.6 ends at once a
    // path whose vertices face against the road).
    if (!orientation) {
        return;
    }
    pugi::xml_node o = lp.append_child("Orientation");
    attr(o, "type", "relative");
    attr(o, "h", std::remainder((p.reversed ? std::numbers::pi : 0.0) + p.heading, 2.0 * std::numbers::pi));
}

void position(pugi::xml_node parent, const LanePlacement& p, bool orientation) {
    lane_position(parent.append_child("Position"), p, orientation);
}

void speed_action(pugi::xml_node parent, const std::string& speed) {
    pugi::xml_node sa = parent.append_child("LongitudinalAction").append_child("SpeedAction");
    pugi::xml_node dyn = sa.append_child("SpeedActionDynamics");
    attr(dyn, "dynamicsShape", "step");
    attr(dyn, "value", 0.0);
    attr(dyn, "dynamicsDimension", "time");
    attr(sa.append_child("SpeedActionTarget").append_child("AbsoluteTargetSpeed"), "value", speed);
}

std::string asset_parameter(const Actor& a, bool is_ego) { return is_ego ? "EgoAsset" : a.name + "Asset"; }

} // namespace railodd::scenario::xosc

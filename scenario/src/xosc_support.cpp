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

void check_revision(const WriteOptions& opt) { check_revision_for(opt.target, opt.rev_minor); }

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

std::string Context::value(std::string_view element, std::string_view name, const std::string& literal) const {
    if (!declared(name)) {
        return literal;
    }
    expressed_.emplace(name);
    if (!target_support::resolves_parameters(opt_.target, element)) {
        return literal; // the declaration's value, as the generator wrote both
    }
    std::string ref{"$"};
    ref += name;
    return ref;
}

bool Context::usable(std::string_view element, target_support::Where where) const {
    return target_support::usable(opt_.target, element, where);
}

void Context::drop(const std::string& name, const std::string& type, const std::string& value,
                   const std::string& reason) const {
    if (std::any_of(dropped_.begin(), dropped_.end(), [&](const Degradation& d) { return d.name == name; })) {
        return;
    }
    const auto it = std::find_if(sc_.parameters.begin(), sc_.parameters.end(),
                                 [&](const Parameter& p) { return p.name == name; });
    if (it == sc_.parameters.end()) {
        added_.push_back({name, type, value});
    }
    dropped_.push_back({name, it == sc_.parameters.end() ? value : it->value, reason});
}

namespace {

// Why a declared parameter that the document does not express stays one.
std::string unexpressed_reason(const Parameter& p) {
    switch (p.role) {
    case ParameterRole::choice:
        return "a template choice no OpenSCENARIO 1.0 action carries (a rail signal's aspect: ScenarioRunner's "
               "TrafficSignalStateAction sets CARLA traffic lights only, and CARLA makes none of a rail signal); "
               "for a controller: the behaviour file's conditions";
    case ParameterRole::degraded_mode:
        return "the degraded mode's id: OpenSCENARIO 1.0 has no degraded modes; of its settings, weather and "
               "rail head are in the Environment, the others are listed beside it";
    case ParameterRole::mode_setting:
        return "a degraded mode's setting no OpenSCENARIO action carries (GNSS, train radio, the sensor's lens, "
               "snow on the track, ...); for a sensor or controller model: the behaviour file's conditions";
    case ParameterRole::storyboard:
        break;
    }
    return "declared, but no element the target reads carries it";
}

} // namespace

std::vector<Degradation> Context::degraded() const {
    std::vector<Degradation> out;
    if (opt_.target == Target::esmini) {
        return out;
    }
    auto dropped = [this](const std::string& name) {
        return std::find_if(dropped_.begin(), dropped_.end(), [&](const Degradation& d) { return d.name == name; });
    };
    // A mode of family none ("all systems nominal") degrades nothing: its id is no loss.
    const bool nominal = std::any_of(sc_.conditions.begin(), sc_.conditions.end(), [](const auto& c) {
        return c.first == "degraded_mode_family" && c.second == "none";
    });
    for (const auto& p : sc_.parameters) {
        if (const auto d = dropped(p.name); d != dropped_.end()) {
            out.push_back(*d);
        } else if (p.role == ParameterRole::degraded_mode && nominal) {
            continue;
        } else if (p.role != ParameterRole::storyboard || !expressed_.contains(p.name)) {
            out.push_back({p.name, p.value, unexpressed_reason(p)});
        }
    }
    for (const auto& p : added_) {
        out.push_back(*dropped(p.name));
    }
    return out;
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

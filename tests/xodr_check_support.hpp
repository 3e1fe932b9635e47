#pragma once
// Handwritten OpenDRIVE documents for the xodr_check tests, and the tests' own
// reference geometry (closed form for lines and arcs, fine Simpson quadrature
// for clothoids), independent of the library under test.
#include "railodd/xodr_check/check.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace railodd::test {

inline std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

struct RefPose {
    double x = 0, y = 0, hdg = 0, k = 0;
};

// One plan-view record as written, with its start pose.
struct Rec {
    std::string kind; // line, arc, spiral
    double s = 0, length = 0;
    RefPose start;
    double k_end = 0; // spiral end curvature (start curvature is start.k)
};

inline RefPose ref_line(RefPose p, double len) {
    return {p.x + len * std::cos(p.hdg), p.y + len * std::sin(p.hdg), p.hdg, 0.0};
}

inline RefPose ref_arc(RefPose p, double k, double len) {
    const double h = p.hdg + k * len;
    return {p.x + (std::sin(h) - std::sin(p.hdg)) / k, p.y - (std::cos(h) - std::cos(p.hdg)) / k, h, k};
}

// Composite Simpson with 1 cm steps: error far below a micrometre per km.
inline RefPose ref_spiral(RefPose p, double k0, double k1, double len) {
    const double rate = (k1 - k0) / len;
    const auto th = [&](double t) { return p.hdg + k0 * t + 0.5 * rate * t * t; };
    const int n = 2 * static_cast<int>(std::ceil(len / 0.02));
    const double h = len / n;
    double sx = 0, sy = 0;
    for (int i = 0; i <= n; ++i) {
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sx += w * std::cos(th(i * h));
        sy += w * std::sin(th(i * h));
    }
    return {p.x + sx * h / 3.0, p.y + sy * h / 3.0, th(len), k1};
}

inline std::string geometry_xml(const Rec& r) {
    std::string g = "<geometry s=\"" + num(r.s) + "\" x=\"" + num(r.start.x) + "\" y=\"" + num(r.start.y) +
                    "\" hdg=\"" + num(r.start.hdg) + "\" length=\"" + num(r.length) + "\">";
    if (r.kind == "line") {
        g += "<line/>";
    } else if (r.kind == "arc") {
        g += "<arc curvature=\"" + num(r.start.k) + "\"/>";
    } else {
        g += "<spiral curvStart=\"" + num(r.start.k) + "\" curvEnd=\"" + num(r.k_end) + "\"/>";
    }
    return g + "</geometry>\n";
}

inline std::string geometries_xml(const std::vector<Rec>& recs) {
    std::string out;
    for (const auto& r : recs) {
        out += geometry_xml(r);
    }
    return out;
}

// line 100, spiral 60 (0 -> 1/500), arc 80, spiral 60 (1/500 -> 0), line 50.
inline std::vector<Rec> rail_alignment(RefPose p, RefPose* end = nullptr) {
    const double k = 1.0 / 500.0;
    std::vector<Rec> recs;
    double s = 0;
    const auto push = [&](const std::string& kind, double len, double k_end, RefPose next) {
        recs.push_back({kind, s, len, p, k_end});
        s += len;
        p = next;
    };
    push("line", 100, 0, ref_line(p, 100));
    push("spiral", 60, k, ref_spiral(p, 0, k, 60));
    push("arc", 80, k, ref_arc(p, k, 80));
    push("spiral", 60, 0, ref_spiral(p, k, 0, 60));
    push("line", 50, 0, ref_line(p, 50));
    if (end) {
        *end = p;
    }
    return recs;
}

inline double total_length(const std::vector<Rec>& recs) {
    return recs.back().s + recs.back().length;
}

inline std::string lanes_xml(const std::string& type) {
    return "<lanes><laneSection s=\"0\"><center><lane id=\"0\" type=\"none\" level=\"false\"/></center>"
           "<right><lane id=\"-1\" type=\"" + type + "\" level=\"false\"><width sOffset=\"0\" a=\"1.435\" b=\"0\" "
           "c=\"0\" d=\"0\"/></lane></right></laneSection></lanes>\n";
}

struct RoadSpec {
    RoadSpec(std::string id_, double length_, std::string geometries_, std::string lane_type_ = "rail",
             std::string link_ = "", std::string junction_ = "-1", std::string extra_ = "")
        : id(std::move(id_)), length(length_), geometries(std::move(geometries_)), lane_type(std::move(lane_type_)),
          link(std::move(link_)), junction(std::move(junction_)), extra(std::move(extra_)) {}
    std::string id;
    double length = 0;
    std::string geometries;
    std::string lane_type;
    std::string link;     // inner XML of <link>
    std::string junction; // "-1" or the junction the road belongs to
    std::string extra;    // elements after <lanes>: objects, signals, railroad
};

inline std::string road_xml(const RoadSpec& r) {
    return "<road name=\"r" + r.id + "\" length=\"" + num(r.length) + "\" id=\"" + r.id + "\" junction=\"" +
           r.junction + "\">\n<link>" + r.link + "</link>\n<planView>\n" + r.geometries + "</planView>\n" +
           lanes_xml(r.lane_type) + r.extra + "</road>\n";
}

inline std::string line_geometry(double x, double y, double hdg, double len) {
    return geometry_xml({"line", 0, len, {x, y, hdg, 0}, 0});
}

inline std::string arc_geometry(double x, double y, double hdg, double k, double len) {
    return geometry_xml({"arc", 0, len, {x, y, hdg, k}, k});
}

inline std::string document(const std::string& body, int rev_minor = 7) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<OpenDRIVE>\n<header revMajor=\"1\" revMinor=\"" +
           std::to_string(rev_minor) + "\" name=\"test\" version=\"1.0\"/>\n" + body + "</OpenDRIVE>\n";
}

inline const xodr_check::Finding* find(const xodr_check::CheckResult& r, const std::string& check,
                                       const std::string& id = "") {
    for (const auto& f : r.findings) {
        if (f.check == check && (id.empty() || f.id == id)) {
            return &f;
        }
    }
    return nullptr;
}

inline std::string listing(const xodr_check::CheckResult& r) {
    std::string out;
    for (const auto& f : r.findings) {
        out += f.object + " " + f.id + " " + f.check + ": " + f.message + "\n";
    }
    return out;
}

} // namespace railodd::test

// A played scenario as a picture (`railodd play --plot`): the map's lanes as
// the player drew them (esmini's odrplot), the recorded paths, the train and
// each actor at the hazard's onset; the whole run on the left, the 160 m
// around the hazard on the right. SVG: no library, opens in any browser.
#include "play_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace railodd::scenario::play {

std::vector<LaneLine> read_lane_lines(std::istream& in) {
    std::vector<LaneLine> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("lane", 0) == 0) {
            LaneLine l;
            l.driving = line.find("no-driving") == std::string::npos;
            out.push_back(std::move(l));
            continue;
        }
        double x = 0.0, y = 0.0;
        if (!out.empty() && std::sscanf(line.c_str(), "%lf, %lf", &x, &y) == 2) {
            out.back().points.push_back({x, y});
        }
    }
    return out;
}

namespace {

struct Window {
    double x0, y0, x1, y1; // world
    double px, py, pw, ph; // panel in the picture
    double scale() const { return std::min(pw / (x1 - x0), ph / (y1 - y0)); }
    bool inside(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    std::string at(double x, double y) const {
        std::ostringstream o;
        o.setf(std::ios::fixed);
        o.precision(1);
        o << px + (x - x0) * scale() << ',' << py + ph - (y - y0) * scale();
        return o.str();
    }
};

Window around(double cx, double cy, double half, double px, double pw, double ph) {
    return {cx - half, cy - half * ph / pw, cx + half, cy + half * ph / pw, px, 40.0, pw, ph};
}

void polyline(std::ostringstream& svg, const Window& w, const std::vector<std::array<double, 2>>& pts,
              const char* style) {
    std::string run;
    auto flush = [&] {
        if (run.find(' ') != std::string::npos) {
            svg << "<polyline points=\"" << run << "\" " << style << "/>\n";
        }
        run.clear();
    };
    for (const auto& p : pts) {
        if (w.inside(p[0], p[1])) {
            run += (run.empty() ? "" : " ") + w.at(p[0], p[1]);
        } else {
            flush();
        }
    }
    flush();
}

std::vector<std::array<double, 2>> path_of(const std::vector<Sample>& v) {
    std::vector<std::array<double, 2>> out;
    for (const Sample& s : v) {
        out.push_back({s.x, s.y});
    }
    return out;
}

void box(std::ostringstream& svg, const Window& w, const Sample& s, double length, double width, const char* fill) {
    const double c = std::cos(s.h), n = std::sin(s.h);
    std::string pts;
    static constexpr std::array<std::array<int, 2>, 4> corners{{{1, 1}, {1, -1}, {-1, -1}, {-1, 1}}};
    for (const auto& [a, b] : corners) {
        const double x = s.x + a * length / 2 * c - b * width / 2 * n, y = s.y + a * length / 2 * n + b * width / 2 * c;
        pts += (pts.empty() ? "" : " ") + w.at(x, y);
    }
    svg << "<polygon points=\"" << pts << "\" fill=\"" << fill << "\" stroke=\"black\" stroke-width=\"0.5\"/>\n";
}

const Sample* at_time(const std::vector<Sample>& v, double t) {
    const Sample* best = v.empty() ? nullptr : &v.front();
    for (const Sample& s : v) {
        if (s.t <= t + 1e-9) {
            best = &s;
        }
    }
    return best;
}

void panel(std::ostringstream& svg, const Window& w, const std::vector<LaneLine>& lanes, const nlohmann::json& sc,
           const Trajectories& run, double t_show) {
    svg << "<rect x=\"" << w.px << "\" y=\"" << w.py << "\" width=\"" << w.pw << "\" height=\"" << w.ph
        << "\" fill=\"#f4f4ef\" stroke=\"#999\"/>\n";
    for (const auto& l : lanes) {
        polyline(svg, w, l.points, l.driving ? R"(fill="none" stroke="#9a9a9a" stroke-width="1")"
                                             : R"(fill="none" stroke="#555" stroke-width="1")");
    }
    for (const auto& [name, v] : run) {
        polyline(svg, w, path_of(v), name == "Ego" ? R"(fill="none" stroke="#1f5fbf" stroke-width="2")"
                                                   : R"(fill="none" stroke="#c0392b" stroke-width="2")");
        const Sample* s = at_time(v, t_show);
        if (!s) {
            continue;
        }
        double length = 1.0, width = 1.0;
        if (name == "Ego") {
            length = sc["ego"].value("length_m", 20.0);
            width = sc["ego"].value("width_m", 3.0);
        }
        for (const auto& a : sc["actors"]) {
            if (a["name"] == name) {
                length = a.value("length_m", 1.0);
                width = a.value("width_m", 1.0);
            }
        }
        box(svg, w, *s, std::max(length, 1.0), std::max(width, 1.0), name == "Ego" ? "#0b2a66" : "#c0392b");
        if (w.inside(s->x, s->y)) {
            // A ring, so the train and the actor show at any scale.
            const std::string xy = w.at(s->x, s->y);
            svg << "<circle cx=\"" << xy.substr(0, xy.find(',')) << "\" cy=\"" << xy.substr(xy.find(',') + 1)
                << "\" r=\"7\" fill=\"none\" stroke=\"" << (name == "Ego" ? "#0b2a66" : "#c0392b")
                << "\" stroke-width=\"1.5\"/>\n";
        }
    }
    const double bar = std::pow(10.0, std::floor(std::log10((w.x1 - w.x0) / 4)));
    svg << "<line x1=\"" << w.px + 10 << "\" y1=\"" << w.py + w.ph - 12 << "\" x2=\"" << w.px + 10 + bar * w.scale()
        << "\" y2=\"" << w.py + w.ph - 12 << "\" stroke=\"black\" stroke-width=\"2\"/><text x=\"" << w.px + 14
        << "\" y=\"" << w.py + w.ph - 18 << "\" font-size=\"11\">" << bar << " m</text>\n";
}

} // namespace

std::string plot_svg(const nlohmann::json& sc, const Trajectories& run, const std::vector<LaneLine>& lanes,
                     const Analysis& a) {
    const auto ego = run.find("Ego");
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const auto& [name, v] : run) {
        for (const Sample& s : v) {
            if (std::isfinite(s.x) && std::isfinite(s.y)) {
                x0 = std::min(x0, s.x), y0 = std::min(y0, s.y), x1 = std::max(x1, s.x), y1 = std::max(y1, s.y);
            }
        }
    }
    if (x0 > x1) {
        return {};
    }
    // The hazard: the first actor's last place; shown at its onset (else the
    // moment the train passes nearest it).
    double hx = 0.5 * (x0 + x1), hy = 0.5 * (y0 + y1), t_show = 0.0;
    const Criticality& c = a.criticality;
    for (const auto& [name, v] : run) {
        if (name != "Ego" && !v.empty()) {
            hx = v.back().x, hy = v.back().y;
            break;
        }
    }
    if (!c.actors.empty() && c.actors.front().onset_s) {
        t_show = *c.actors.front().onset_s;
    } else if (ego != run.end()) {
        double best = std::numeric_limits<double>::infinity();
        for (const Sample& s : ego->second) {
            if (const double d = std::hypot(s.x - hx, s.y - hy); d < best) {
                best = d, t_show = s.t;
            }
        }
    }
    const double half = 0.55 * std::max({x1 - x0, y1 - y0, 50.0});
    const Window whole = around(0.5 * (x0 + x1), 0.5 * (y0 + y1), half, 10, 580, 520);
    const Window zoom = around(hx, hy, 80.0, 610, 580, 520);
    std::ostringstream svg;
    svg << R"(<svg xmlns="http://www.w3.org/2000/svg" width="1200" height="600" font-family="sans-serif">)" << "\n";
    svg << "<text x=\"10\" y=\"24\" font-size=\"15\">" << sc.value("id", "") << ": "
        << std::lround(c.ego_speed_mps * 3.6) << " km/h, stops in " << std::lround(c.stopping_distance_m)
        << " m, sees " << std::lround(c.sight_distance_m) << " m (" << c.sight_limited_by << "): "
        << (c.can_stop ? "can stop" : "cannot stop") << (a.passed() ? "" : "; FAILS its checks") << "; shown at t = "
        << std::lround(t_show * 10) / 10.0 << " s</text>\n";
    panel(svg, whole, lanes, sc, run, t_show);
    panel(svg, zoom, lanes, sc, run, t_show);
    svg << "<text x=\"610\" y=\"590\" font-size=\"11\">blue: train, red: " << (sc["actors"].empty() ? "" : sc["actors"][0].value("name", ""))
        << "; dark lines: rail lanes, grey: road lanes (esmini odrplot)</text>\n</svg>\n";
    return svg.str();
}

} // namespace railodd::scenario::play

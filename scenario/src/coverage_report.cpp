// coverage.json and the readable table printed by `railodd scenarios`.
#include "railodd/scenario/coverage.hpp"

#include "coverage_gaps.hpp"

#include <cstdio>

namespace railodd::scenario {

namespace {

using ojson = nlohmann::ordered_json;

std::size_t covered(const std::vector<CoverageItem>& items) {
    std::size_t n = 0;
    for (const auto& i : items) {
        n += i.scenarios > 0 ? 1 : 0;
    }
    return n;
}

// Spec items the route can host: all but infrastructure it does not have.
std::size_t hostable(const std::vector<CoverageItem>& items) {
    std::size_t n = 0;
    for (const auto& i : items) {
        n += i.reason == not_on_route ? 0 : 1;
    }
    return n;
}

double ratio(std::size_t a, std::size_t b) { return b == 0 ? 1.0 : static_cast<double>(a) / static_cast<double>(b); }

ojson items_json(const std::vector<CoverageItem>& items) {
    ojson out = ojson::array();
    for (const auto& i : items) {
        ojson j = {{"element", i.element}, {"attribute", i.attribute}, {"class", i.value_class},
                   {"on_route", i.on_route}, {"scenarios", i.scenarios}};
        if (i.scenarios == 0 && !i.reason.empty()) {
            j["reason"] = i.reason;
        }
        out.push_back(std::move(j));
    }
    return out;
}

std::string label(const CoverageItem& i) {
    return i.attribute.empty() ? i.element : i.element + " | " + i.attribute + " = " + i.value_class;
}

ojson infeasible_values(const TemplateRun& r) {
    ojson out = ojson::array();
    for (const auto& [name, value] : r.infeasible_values) {
        out.push_back({{"parameter", name}, {"value", value}});
    }
    return out;
}

// Under the cover strategy: the set against pairwise over all anchors and
// the full factorial of the same templates.
struct Selection {
    bool cover = false;
    std::size_t pairwise = 0;
    double full = 0.0;
};

Selection selection(const Coverage& c) {
    Selection s;
    for (const auto& r : c.runs) {
        s.cover = s.cover || r.full_factorial > 0.0;
        s.pairwise += r.pairwise_rows;
        s.full += r.full_factorial;
    }
    return s;
}

} // namespace

ojson coverage_json(const Coverage& c) {
    ojson j;
    j["railodd"] = {{"format", "scenario_coverage"}, {"format_version", 1}};
    j["scenarios"] = c.scenarios;
    if (const Selection sel = selection(c); sel.cover) {
        j["selection"] = {{"strategy", "cover"}, {"scenarios", c.scenarios}, {"pairwise_scenarios", sel.pairwise},
                          {"full_factorial_scenarios", sel.full},
                          {"ratio_to_pairwise", ratio(c.scenarios, sel.pairwise)}};
    }
    j["route"] = {{"items", c.route.size()}, {"covered", covered(c.route)},
                  {"ratio", ratio(covered(c.route), c.route.size())}, {"elements", items_json(c.route)}};
    j["exercised"] = items_json(c.exercised);
    if (!c.spec_name.empty() || !c.spec.empty()) {
        j["spec"] = {{"name", c.spec_name}, {"items", c.spec.size()}, {"covered", covered(c.spec)},
                     {"ratio", ratio(covered(c.spec), c.spec.size())}, {"hostable", hostable(c.spec)},
                     {"elements", items_json(c.spec)}};
    }
    ojson pairs = ojson::array();
    for (const auto& r : c.runs) {
        ojson dims = ojson::array();
        for (std::size_t d = 0; d < r.dimensions.size(); ++d) {
            dims.push_back({{"name", r.dimensions[d]}, {"values", r.sizes[d]}});
        }
        ojson skipped = ojson::array();
        for (const auto& s : r.skipped) {
            skipped.push_back({{"element", s.element}, {"reason", s.reason}});
        }
        pairs.push_back({{"template", r.template_id}, {"anchors", r.anchors}, {"anchors_skipped", std::move(skipped)},
                         {"anchors_infeasible", r.infeasible.size()}, {"infeasible_values", infeasible_values(r)},
                         {"rows", r.rows}, {"dimensions", std::move(dims)}, {"pairs_feasible", r.pairs.feasible},
                         {"pairs_covered", r.pairs.covered}, {"pairs_infeasible", r.pairs.infeasible},
                         {"ratio", ratio(r.pairs.covered, r.pairs.feasible)}});
    }
    j["templates"] = std::move(pairs);
    ojson gaps = ojson::array();
    for (const auto* list : {&c.route, &c.spec}) {
        for (const auto& i : *list) {
            if (i.scenarios == 0) {
                gaps.push_back({{"element", i.element}, {"attribute", i.attribute}, {"class", i.value_class},
                                {"in", list == &c.route ? "route" : "spec"}, {"on_route", i.on_route},
                                {"reason", i.reason}});
            }
        }
    }
    j["gaps"] = std::move(gaps);
    return j;
}

std::string coverage_table(const Coverage& c) {
    std::string out;
    char buf[512];
    const Selection sel = selection(c);
    std::snprintf(buf, sizeof buf, "%zu scenarios\n", c.scenarios);
    out += buf;
    if (sel.cover) {
        std::snprintf(buf, sizeof buf,
                      "cover: %zu scenarios cover what pairwise over all anchors covers with %zu (%.1f%%); the full "
                      "factorial has %.0f\n",
                      c.scenarios, sel.pairwise, 100.0 * ratio(c.scenarios, sel.pairwise), sel.full);
        out += buf;
    }
    out += sel.cover ? "\nTemplates (pairwise coverage of the parameters' values)\n"
                     : "\nTemplates (pairwise coverage of parameter values)\n";
    std::snprintf(buf, sizeof buf, "  %-34s %8s %8s %10s %10s\n", "template", "anchors", "rows", "pairs", "covered");
    out += buf;
    for (const auto& r : c.runs) {
        std::snprintf(buf, sizeof buf, "  %-34s %8zu %8zu %10zu %9.1f%%\n", r.template_id.c_str(), r.anchors, r.rows,
                      r.pairs.feasible, 100.0 * ratio(r.pairs.covered, r.pairs.feasible));
        out += buf;
    }
    auto section = [&](const char* title, const std::vector<CoverageItem>& items) {
        std::snprintf(buf, sizeof buf, "\n%s: %zu of %zu covered (%.1f%%)\n", title, covered(items), items.size(),
                      100.0 * ratio(covered(items), items.size()));
        out += buf;
        for (const auto& i : items) {
            std::snprintf(buf, sizeof buf, "  %-3s %-86s %7zu %7zu\n", i.scenarios > 0 ? "ok" : "GAP",
                          label(i).c_str(), i.on_route, i.scenarios);
            out += buf;
            if (i.scenarios == 0 && !i.reason.empty()) {
                out += "        " + i.reason + "\n";
            }
        }
    };
    section("ODD elements and classes on the route (on route / scenarios)", c.route);
    section("Dynamic elements and conditions the scenarios add (- / scenarios)", c.exercised);
    if (!c.spec.empty()) {
        section(("ODD spec '" + c.spec_name + "' (on route / scenarios; the route can host " +
                 std::to_string(hostable(c.spec)) + ")").c_str(), c.spec);
    }
    return out;
}

} // namespace railodd::scenario

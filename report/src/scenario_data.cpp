// A scenario set in the page: what was selected and why, the coverage matrix
// of ODD items by template (from each scenario's odd_elements in the
// manifest), the gaps with their reasons, each scenario's anchor, and with
// play results each scenario's verdict and criticality.
#include "parts.hpp"

#include "railodd/util/errors.hpp"

#include <fstream>
#include <set>
#include <tuple>
#include <optional>

namespace railodd::report::detail {

namespace {


using Item = std::tuple<std::string, std::string, std::string>; // element, attribute, class

Item item_of(const ojson& j) {
    return {j.value("element", ""), j.value("attribute", ""), j.value("class", "")};
}

// Items of the route, the spec and those exercised only by scenarios
// (weather, light), each once, in that order.
ojson matrix_json(const ojson& coverage, const ojson& manifest) {
    std::vector<Item> items;
    std::map<Item, std::size_t> index;
    std::vector<std::pair<std::size_t, bool>> flags; // on_route, in_spec
    const auto add = [&](const ojson& list, bool spec) {
        for (const auto& e : list) {
            const Item it = item_of(e);
            auto [pos, fresh] = index.emplace(it, items.size());
            if (fresh) {
                items.push_back(it);
                flags.push_back({e.value("on_route", std::size_t{0}), false});
            }
            flags[pos->second].second = flags[pos->second].second || spec;
        }
    };
    add(coverage.value("route", ojson::object()).value("elements", ojson::array()), false);
    if (coverage.contains("spec") && coverage["spec"].is_object()) {
        add(coverage["spec"].value("elements", ojson::array()), true);
    }
    add(coverage.value("exercised", ojson::array()), false);
    std::vector<std::string> templates;
    std::map<std::string, std::size_t> tindex;
    std::vector<std::vector<std::size_t>> counts(items.size());
    for (const auto& sc : manifest.value("scenarios", ojson::array())) {
        const std::string t = sc.value("template", "");
        auto [tp, fresh] = tindex.emplace(t, templates.size());
        if (fresh) {
            templates.push_back(t);
        }
        std::set<std::size_t> hit;
        for (const auto& oe : sc.value("odd_elements", ojson::array())) {
            if (const auto it = index.find(item_of(oe)); it != index.end()) {
                hit.insert(it->second);
            }
        }
        for (std::size_t i : hit) {
            counts[i].resize(templates.size(), 0);
            ++counts[i][tp->second];
        }
    }
    Array item_rows, count_rows;
    for (std::size_t i = 0; i < items.size(); ++i) {
        item_rows.push_back({{"element", std::get<0>(items[i])}, {"attribute", std::get<1>(items[i])},
                             {"class", std::get<2>(items[i])}, {"on_route", flags[i].first},
                             {"in_spec", flags[i].second}});
        counts[i].resize(templates.size(), 0);
        count_rows.push_back(counts[i]);
    }
    return {{"items", ojson(std::move(item_rows))}, {"templates", templates}, {"counts", ojson(std::move(count_rows))}};
}

ojson play_of(const ojson& result) {
    ojson failed = ojson::array();
    for (const auto& c : result.value("checks", ojson::array())) {
        if (!c.value("passed", true)) {
            failed.push_back(c.value("check", "") + (c.value("detail", "").empty() ? "" : ": " + c.value("detail", "")));
        }
    }
    return {{"passed", result.value("passed", false)}, {"ran", result.value("ran", false)},
            {"failed_checks", std::move(failed)}, {"criticality", result.value("criticality", ojson(nullptr))}};
}

ojson scenario_list(const ojson& manifest, const ojson* play, const RoadData& roads) {
    std::map<std::string, const ojson*> results;
    if (play && play->contains("scenarios")) {
        for (const auto& r : play->at("scenarios")) { // by reference: the map keeps pointers
            results[r.value("id", "")] = &r;
        }
    }
    Array list;
    for (const auto& sc : manifest.value("scenarios", ojson::array())) {
        const ojson anchor = sc.value("anchor", ojson::object());
        const std::string id = sc.value("id", "");
        const auto r = results.find(id);
        list.push_back({{"id", id}, {"template", sc.value("template", "")}, {"text", sc.value("text", "")},
                        {"element", anchor.value("element", "")}, {"road", roads.index_of(anchor.value("road_id", ""))},
                        {"s", cm(anchor.value("s", 0.0))}, {"track", anchor.value("track", 0)},
                        {"chainage", cm(anchor.value("chainage", 0.0))},
                        {"play", r == results.end() ? ojson(nullptr) : play_of(*r->second)}});
    }
    return ojson(std::move(list));
}

ojson ratio_part(const ojson& j, std::initializer_list<const char*> keys) {
    ojson out = ojson::object();
    for (const char* k : keys) {
        if (j.contains(k)) {
            out[k] = j[k];
        }
    }
    return out;
}

} // namespace

ojson scenario_section(const std::filesystem::path& dir, const std::filesystem::path& play_file, const RoadData& roads) {
    const ojson coverage = read_checked_json(dir / "coverage.json", "scenario coverage", coverage_shape());
    const ojson manifest = read_checked_json(dir / "manifest.json", "scenario manifest", manifest_shape());
    std::optional<ojson> play;
    if (!play_file.empty()) {
        play = read_checked_json(play_file, "play results", play_shape());
    }
    ojson templates = ojson::array();
    for (const auto& t : coverage.value("templates", ojson::array())) {
        templates.push_back(ratio_part(t, {"template", "rows", "anchors", "anchors_infeasible", "pairs_feasible",
                                           "pairs_covered", "pairs_infeasible", "ratio"}));
    }
    const ojson spec = coverage.value("spec", ojson(nullptr));
    return {{"dir", dir.string()},
            {"count", manifest.value("scenarios", ojson::array()).size()},
            {"strategy", manifest.value("generation", ojson::object()).value("strategy", "")},
            {"selection", coverage.value("selection", ojson::object())},
            {"route", ratio_part(coverage.value("route", ojson::object()), {"items", "covered", "ratio"})},
            {"spec", spec.is_object() ? ratio_part(spec, {"name", "items", "covered", "hostable", "ratio"}) : ojson(nullptr)},
            {"templates", std::move(templates)},
            {"matrix", matrix_json(coverage, manifest)},
            {"gaps", coverage.value("gaps", ojson::array())},
            {"criticality", coverage.value("criticality", ojson(nullptr))},
            {"list", scenario_list(manifest, play ? &*play : nullptr, roads)},
            {"play", play ? ojson{{"player", play->value("player", ojson::object()).value("path", "")},
                                  {"version", play->value("player", ojson::object()).value("version", "")},
                                  {"summary", play->value("summary", ojson::object())}}
                          : ojson(nullptr)}};
}

} // namespace railodd::report::detail

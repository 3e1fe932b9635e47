#include "scenarios_command.hpp"
#include "scenario_maps.hpp"
#include "option_checks.hpp"

#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/coverage.hpp"
#include "railodd/scenario/generator.hpp"
#include "railodd/scenario/outputs.hpp"
#include "railodd/scenario/templates.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/util/file_names.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/json_input.hpp"
#include "railodd/util/output_stage.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

namespace railodd::cli {

namespace fs = std::filesystem;

namespace {

std::string or_default(const std::string& given, const char* shipped) {
    return given.empty() ? (fs::path{RAILODD_DATA_DIR} / shipped).string() : given;
}

// The map's header date, so that the scenario files change only with the map.
// The scenarios reference the map: one that is not an OpenDRIVE document
// from start to end (not XML, truncated) is refused rather than referenced.
// A whole parse is `railodd validate`'s job.
std::string map_date(const fs::path& xodr) {
    require_input_file(xodr, "OpenDRIVE map (run `railodd convert` first)");
    std::ifstream in(xodr, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    std::string tail(64, '\0');
    in.clear();
    in.seekg(0, std::ios::end);
    const auto size = static_cast<std::streamoff>(in.tellg());
    in.seekg(std::max<std::streamoff>(0, size - static_cast<std::streamoff>(tail.size())));
    in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
    tail.resize(static_cast<std::size_t>(in.gcount()));
    if (head.find("<OpenDRIVE") == std::string::npos || head.find("<header") == std::string::npos ||
        tail.find("</OpenDRIVE>") == std::string::npos) {
        throw InputError(xodr.string(), "not an OpenDRIVE map (no <OpenDRIVE> with a <header> at its start, or "
                                        "no </OpenDRIVE> at its end: truncated?)");
    }
    std::smatch m;
    static const std::regex date(R"(<header[^>]*\bdate="(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d)Z?")");
    return std::regex_search(head, m, date) ? m[1].str() : "2026-01-01T00:00:00";
}

// The manifest of an earlier run in the output folder, or null: a file that
// is not one (edited, damaged, a folder) only means nothing is removed.
nlohmann::json old_manifest(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        return nullptr;
    }
    try {
        nlohmann::json j = read_json_file<nlohmann::json>(file, "earlier scenario manifest");
        return j.is_object() ? std::move(j) : nlohmann::json(nullptr);
    } catch (const InputError&) {
        return nullptr;
    }
}

// The files an earlier run's manifest lists: its scenarios, behaviours and
// distributions, and what `railodd play` wrote of them. Those this run does not write again are removed in its
// commit; only names railodd itself writes there are taken, whatever the old
// manifest says.
std::vector<std::string> earlier_files(const nlohmann::json& old) {
    std::vector<std::string> out;
    auto take = [&out](const nlohmann::json& entry, const char* key, const char* folder, std::string_view tail) {
        if (!entry.is_object() || !entry.contains(key) || !entry[key].is_string()) {
            return;
        }
        std::string name = entry[key].get<std::string>();
        if (folder && name.rfind(folder, 0) == 0) {
            name.erase(0, std::string_view{folder}.size());
        } else if (folder) {
            return;
        }
        if (is_safe_name(name) && name.ends_with(tail)) {
            out.push_back((folder ? folder : "") + name);
        }
    };
    for (const char* list : {"scenarios", "templates"}) {
        if (!old.is_object() || !old.contains(list) || !old[list].is_array()) {
            continue;
        }
        for (const auto& e : old[list]) {
            take(e, "file", nullptr, ".xosc");
            take(e, "behavior", nullptr, ".behavior.yaml");
            take(e, "distribution", "distributions/", ".xosc");
            // `railodd play`'s recordings of the earlier set: stale now.
            if (list == std::string_view{"scenarios"} && e.is_object() && e.contains("id") && e["id"].is_string() &&
                is_safe_name(e["id"].get<std::string>())) {
                out.push_back("play/" + e["id"].get<std::string>() + ".csv");
                out.push_back("play/" + e["id"].get<std::string>() + ".log");
            }
        }
    }
    if (!out.empty()) {
        out.push_back("play.json");
        out.push_back("play.txt");
    }
    return out;
}

} // namespace

CLI::App* ScenariosCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "scenarios", "Generate route-anchored OpenSCENARIO scenarios from templates (docs/scenarios.md)");
    app->add_option("--map", opt_.map_dir, "Output folder of `railodd convert` (map.xodr, odd_profile.json)")
        ->required();
    app->add_option("-o,--output", opt_.out_dir, "Folder for the scenarios")->required()->check(non_empty_path);
    app->add_option("--templates", opt_.templates, "Base-scenario templates (default: data/scenario/templates.yaml)");
    app->add_option("--catalog", opt_.catalog, "Asset catalog (default: data/scenario/assets.yaml)");
    app->add_option("--taxonomy", opt_.taxonomy, "ODD taxonomy (default: data/odd/railway_odd.yaml)");
    app->add_option("--odd-spec", opt_.odd_spec, "Declared ODD: coverage.json also lists its gaps");
    app->add_option("--strategy", opt_.strategy, "cover (every ODD element and class of the route, pairwise over parameters), pairwise, full or random")->capture_default_str();
    app->add_option("--count", opt_.count, "Scenarios per template (random: required; others: at most; at most 100000)")
        ->check(unsigned_integer);
    app->add_option("--seed", opt_.seed, "Seed of the random strategy")->capture_default_str()->check(unsigned_integer);
    app->add_option("--max-anchors", opt_.max_anchors, "Anchors per template, spread along the route (0: all)")
        ->check(unsigned_integer)
        ->capture_default_str();
    app->add_option("--osc-version", opt_.osc_version,
                    "OpenSCENARIO version: 1.1, 1.2 (default) or 1.3; 1.0 under --target carla");
    app->add_option("--target", opt_.target,
                    "Player: esmini, or carla (ScenarioRunner: OpenSCENARIO 1.0, only what it supports)")
        ->capture_default_str();
    app->add_option("--map-corridor", opt_.map_corridor_m,
                    "Give each scenario a map cut to the roads within METERS of its route (0: the whole map; "
                    "default: 200 for maps over 5 MB, else 0)")
        ->check(finite_range(0.0, 100000.0));
    app->add_flag("-q,--quiet", opt_.quiet, "Do not print the coverage table");
    return app;
}

void ScenariosCommand::setup() {
    try {
        scenario::strategy_from(opt_.strategy);
    } catch (const std::invalid_argument& e) {
        throw UsageError("--strategy", e.what());
    }
    if (opt_.strategy == "random" && opt_.count == 0) {
        throw UsageError("--count", "the random strategy needs --count N (N > 0)");
    }
    if (opt_.count > scenario::max_count_per_template) {
        throw UsageError("--count", std::to_string(opt_.count) + " is more than the " +
                                        std::to_string(scenario::max_count_per_template) +
                                        " scenarios per template railodd generates");
    }
    try {
        target_ = scenario::target_from(opt_.target);
    } catch (const std::invalid_argument& e) {
        throw UsageError("--target", e.what());
    }
    if (opt_.osc_version.empty()) {
        osc_minor_ = scenario::default_revision(target_);
    } else if (target_ == scenario::Target::carla && opt_.osc_version != "1.0") {
        throw UsageError("--osc-version", "'" + opt_.osc_version +
                                              "': --target carla writes OpenSCENARIO 1.0, the only version "
                                              "ScenarioRunner reads");
    } else if (target_ == scenario::Target::esmini && opt_.osc_version != "1.1" && opt_.osc_version != "1.2" &&
               opt_.osc_version != "1.3") {
        throw UsageError("--osc-version", "'" + opt_.osc_version + "' is not 1.1, 1.2 or 1.3 (1.0: --target carla)");
    } else {
        osc_minor_ = opt_.osc_version.back() - '0';
    }
    if (!fs::is_directory(opt_.map_dir)) {
        throw InputError(opt_.map_dir, "not a folder (give the output folder of `railodd convert`)");
    }
}

int ScenariosCommand::run() {
    // Read the map: its ODD profile, where it lies and its date
    const fs::path map_dir{opt_.map_dir};
    finish_pending_commit(map_dir); // the map folder as its last run left it, not half committed
    const odd::OddProfile profile = odd::read_profile(map_dir / "odd_profile.json");
    const fs::path xodr = map_dir / "map.xodr";
    const std::string date = map_date(xodr);

    // Read the taxonomy, the catalog and the templates, each checked against the ones before
    const std::string taxonomy_file = or_default(opt_.taxonomy, "odd/railway_odd.yaml");
    const odd::Taxonomy taxonomy = odd::load_taxonomy(taxonomy_file);
    const std::string catalog_file = or_default(opt_.catalog, "scenario/assets.yaml");
    const scenario::Catalog catalog = scenario::load_catalog(catalog_file, taxonomy);
    scenario::check_catalog_for(catalog, target_);
    const std::string templates_file = or_default(opt_.templates, "scenario/templates.yaml");
    const scenario::TemplateSet templates = scenario::load_templates(templates_file, taxonomy, catalog);
    std::optional<odd::OddSpec> spec;
    if (!opt_.odd_spec.empty()) {
        spec = odd::load_odd_spec(opt_.odd_spec, taxonomy);
    }

    // Anchor the templates on the route and instantiate them
    OutputStage stage(opt_.out_dir);
    const fs::path out = fs::absolute(opt_.out_dir).lexically_normal();
    scenario::GenerateOptions gen;
    gen.strategy = scenario::strategy_from(opt_.strategy);
    gen.count = opt_.count;
    gen.seed = opt_.seed;
    gen.max_anchors = opt_.max_anchors;
    gen.map_file = fs::absolute(xodr).lexically_normal().lexically_relative(out).generic_string();
    gen.date = date;
    gen.target = target_;
    gen.connecting_roads = connecting_roads(xodr);
    scenario::Generation generation = scenario::generate(profile, templates, catalog, taxonomy, gen);
    if (const double corridor = corridor_for(opt_.map_corridor_m, xodr); corridor > 0.0) {
        cut_scenario_maps(stage, xodr, corridor, generation);
    }

    // Coverage of the route's ODD (and the declared one)
    const scenario::Coverage coverage =
        scenario::compute_coverage(profile, taxonomy, generation, spec ? &*spec : nullptr, &templates);

    // Write everything, then move it into place
    scenario::OutputInfo info{map_dir.string(), gen.map_file, taxonomy_file, catalog_file, templates_file,
                              opt_.odd_spec, gen.strategy, opt_.count, opt_.seed, osc_minor_, date, target_};
    scenario::write_scenario_set(stage, generation, coverage, profile, info);
    for (const auto& name : earlier_files(old_manifest(out / "manifest.json"))) {
        stage.remove_on_commit(name); // unless written again
    }
    stage.commit();
    if (!opt_.quiet) {
        std::cout << scenario::coverage_table(coverage);
    }
    for (const auto& r : generation.runs) {
        if (r.every_valid_row) {
            std::cout << "template " << r.template_id << ": only " << r.rows
                      << " distinct valid parameter rows exist, fewer than --count " << opt_.count
                      << ": all of them generated\n";
        }
    }
    std::cout << "wrote " << generation.scenarios.size() << " scenarios to " << opt_.out_dir << '\n';
    return exit_ok;
}

} // namespace railodd::cli

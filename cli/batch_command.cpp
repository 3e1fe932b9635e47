#include "batch_command.hpp"
#include "option_checks.hpp"

#include "batch_routes.hpp"
#include "batch_runner.hpp"
#include "batch_stamp.hpp"

#include "railodd/util/errors.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <regex>
#include <thread>

#include <unistd.h>

namespace railodd::cli {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

CLI::App* BatchCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand("batch", "Convert many routes from a routes file in parallel (docs/batch.md)");
    app->add_option("ROUTES", opt_.routes_file, "Routes file (YAML): ids, inputs, selections, options")->required();
    app->add_option("-o,--output", opt_.outroot, "Output root: one folder per route id")->required()->check(non_empty_path);
    app->add_option("-j,--jobs", opt_.jobs, "Routes run at once (default: hardware threads)")
        ->check(CLI::Range(1u, 4096u));
    app->add_option("--shard", opt_.shard, "Run only shard I of N (I/N, 0-based: routes k with k mod N = I)")
        ->capture_default_str();
    app->add_flag("--force", opt_.force, "Rerun routes whose outputs are up to date");
    app->add_option("--route-timeout", opt_.route_timeout_s,
                    "Seconds a route may run before it is killed and reported as timed out; the others go on (0: no "
                    "limit)")
        ->capture_default_str()
        ->check(finite_range(0.0, 1e7));
    return app;
}

void BatchCommand::setup() {
    std::smatch m;
    static const std::regex shard(R"((\d{1,6})/(\d{1,6}))");
    if (!std::regex_match(opt_.shard, m, shard) || std::stoul(m[2]) == 0 || std::stoul(m[1]) >= std::stoul(m[2]) ||
        std::stoul(m[2]) > max_shards) {
        throw UsageError("--shard", "'" + opt_.shard + "' must be I/N with 0 <= I < N <= " + std::to_string(max_shards) +
                                        " (0-based, e.g. 0/10 .. 9/10)");
    }
    shard_index_ = static_cast<unsigned>(std::stoul(m[1]));
    shard_count_ = static_cast<unsigned>(std::stoul(m[2]));
    if (opt_.jobs == 0) {
        opt_.jobs = std::max(1u, std::thread::hardware_concurrency());
    }
}

namespace {

struct RouteResult {
    const BatchRoute* route = nullptr;
    std::string status = "pending"; // ok, failed, skipped
    TaskOutcome outcome;
};

// Shard files carry I and N in their names so that array-job shards writing
// into one OUTROOT never overwrite each other's summary.
std::string shard_suffix(unsigned index, unsigned count) {
    return count == 1 ? "" : ".shard-" + std::to_string(index) + "-of-" + std::to_string(count);
}

void write_json(const fs::path& path, const json& j) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << j.dump(2) << '\n';
        if (!out) {
            throw OutputError(tmp.string(), "cannot write");
        }
    }
    fs::rename(tmp, path);
}

// The deterministic part: same routes file and inputs, same bytes, whatever
// --jobs and the machine's load. Timings go to batch_timings*.json.
json summary_json(const BatchFile& file, const std::vector<RouteResult>& results, unsigned index, unsigned count) {
    json s;
    s["railodd"] = {{"format", "batch_summary"}, {"format_version", 1}, {"version", railodd_version}};
    s["routes_file"] = file.path.filename().string();
    s["routes_file_hash"] = file.content_hash;
    s["routes_total"] = file.routes.size();
    s["shard"] = {{"index", index}, {"count", count}};
    json counts = {{"ok", 0}, {"failed", 0}, {"skipped", 0}};
    json routes = json::array();
    for (const auto& r : results) {
        counts[r.status] = counts[r.status].get<int>() + 1;
        json e = {{"id", r.route->id}, {"line", r.route->line}, {"status", r.status},
                  {"scenarios", r.route->scenarios}};
        if (r.status == "failed") {
            e["exit_code"] = r.outcome.exit_code;
            e["failed_step"] = r.outcome.failed_step;
            e["error"] = r.outcome.error;
        }
        routes.push_back(std::move(e));
    }
    s["counts"] = std::move(counts);
    s["routes"] = std::move(routes);
    return s;
}

json timings_json(const std::vector<RouteResult>& results, unsigned jobs, double wall) {
    json t;
    t["railodd"] = {{"format", "batch_timings"}, {"format_version", 1}};
    t["jobs"] = jobs;
    t["wall_s"] = wall;
    json routes = json::array();
    for (const auto& r : results) {
        routes.push_back({{"id", r.route->id}, {"status", r.status}, {"seconds", r.outcome.seconds},
                          {"peak_rss_kb", r.outcome.peak_rss_kb}});
    }
    t["routes"] = std::move(routes);
    return t;
}

void print_table(const std::vector<RouteResult>& results, const json& counts, double wall) {
    std::printf("railodd batch: %d ok, %d failed, %d skipped in %.1f s\n", counts["ok"].get<int>(),
                counts["failed"].get<int>(), counts["skipped"].get<int>(), wall);
    std::printf("  %-24s %-8s %9s %12s  %s\n", "route", "status", "seconds", "peak RSS MB", "error");
    for (const auto& r : results) {
        if (r.status == "skipped") {
            std::printf("  %-24s %-8s %9s %12s  %s\n", r.route->id.c_str(), "skipped", "-", "-", "up to date");
            continue;
        }
        std::printf("  %-24s %-8s %9.1f %12.1f  %s\n", r.route->id.c_str(), r.status.c_str(), r.outcome.seconds,
                    r.outcome.peak_rss_kb / 1024.0, r.outcome.error.c_str());
    }
    std::fflush(stdout);
}

// The steps run in OUTROOT on the relative folder ID (inputs are absolute):
// paths the outputs record (manifest.json's map_dir) are then the same
// wherever OUTROOT is, and the outputs of two roots compare byte for byte.
BatchTask make_task(const BatchRoute& route, const fs::path& root, bool single_thread, double timeout_s) {
    const fs::path abs = fs::absolute(root);
    const fs::path dir{route.id};
    BatchTask t{route.id, {{"convert", convert_args(route, dir, single_thread), abs / dir / "convert.log", abs, {}}},
                route.timeout_s.value_or(timeout_s)};
    if (route.scenarios) {
        t.steps.push_back({"scenarios", scenarios_args(route, dir), abs / dir / "scenarios.log", abs, {}});
    }
    return t;
}

int batch_exit_code(const std::vector<RouteResult>& results) {
    int code = exit_ok;
    for (const auto& r : results) {
        if (r.status == "failed") {
            const int c = r.outcome.exit_code;
            code = std::max(code, c >= exit_usage && c <= exit_internal ? c : int{exit_internal});
        }
    }
    return code;
}

} // namespace

int BatchCommand::run() {
    const auto t0 = std::chrono::steady_clock::now();
    const BatchFile file = load_batch_file(opt_.routes_file);
    const fs::path root{opt_.outroot};
    std::error_code ec;
    fs::create_directories(root, ec);
    if (ec || !fs::is_directory(root)) {
        throw OutputError(root.string(), "cannot create the output root");
    }
    std::vector<RouteResult> results;
    for (std::size_t k = 0; k < file.routes.size(); ++k) {
        if (k % shard_count_ == shard_index_) {
            results.push_back(RouteResult{&file.routes[k], "pending", {}});
        }
    }
    BatchProgress progress(results.size(), opt_.jobs, ::isatty(STDERR_FILENO) == 1);
    std::vector<BatchTask> tasks;
    std::vector<std::size_t> task_result;
    std::vector<json> stamps(results.size());
    for (std::size_t i = 0; i < results.size(); ++i) {
        const BatchRoute& route = *results[i].route;
        const fs::path dir = root / route.id;
        stamps[i] = make_stamp(route);
        if (!opt_.force && up_to_date(dir, route, stamps[i])) {
            results[i].status = "skipped";
            progress.finished(route.id, "skipped", 0.0, "up to date");
            continue;
        }
        fs::create_directories(dir, ec);
        if (ec) {
            throw OutputError(dir.string(), "cannot create the route's folder: " + ec.message());
        }
        remove_stamp(dir);
        tasks.push_back(make_task(route, root, opt_.jobs > 1, opt_.route_timeout_s));
        task_result.push_back(i);
    }
    run_tasks(
        tasks, opt_.jobs, progress, [&](std::size_t t, const TaskOutcome& o) {
        RouteResult& r = results[task_result[t]];
        r.outcome = o;
        r.status = o.ok ? "ok" : "failed";
        try {
            if (o.ok) {
                write_stamp(root / r.route->id, stamps[task_result[t]]);
            }
        } catch (const std::exception& e) { // the other routes keep running
            r.status = "failed";
            r.outcome = {false, exit_output, o.seconds, o.peak_rss_kb, "stamp", e.what()};
        }
        progress.finished(r.route->id, r.status, o.seconds,
                          r.outcome.ok ? "" : r.outcome.failed_step + ": " + r.outcome.error);
        });
    progress.close();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string suffix = shard_suffix(shard_index_, shard_count_);
    const json summary = summary_json(file, results, shard_index_, shard_count_);
    write_json(root / ("batch_summary" + suffix + ".json"), summary);
    write_json(root / ("batch_timings" + suffix + ".json"), timings_json(results, opt_.jobs, wall));
    print_table(results, summary["counts"], wall);
    return batch_exit_code(results);
}

} // namespace railodd::cli

// Template by template: anchors on the route form the first dimension, the
// varied parameters the others; the strategy picks rows that respect the
// constraints, and every row becomes one scenario.
#include "railodd/scenario/generator.hpp"

#include "attribute_values.hpp"
#include "instantiate.hpp"
#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <set>
#include <tuple>
#include <stdexcept>

namespace railodd::scenario {

namespace {

// Anchors spread evenly along the list when there are more than `max`.
std::vector<Anchor> thin(std::vector<Anchor> anchors, std::size_t max) {
    if (max == 0 || anchors.size() <= max) {
        return anchors;
    }
    std::vector<Anchor> out;
    for (std::size_t i = 0; i < max; ++i) {
        const std::size_t k = max == 1 ? 0 : (i * (anchors.size() - 1) + (max - 1) / 2) / (max - 1);
        out.push_back(anchors[k]);
    }
    return out;
}

bool set(const Row& r, std::size_t d) { return r[d] != kUnset; }

// The constraints of a template on a (partial) row.
Validity validity(const TemplateContext& ctx) {
    return [&ctx](const Row& r) {
        const Template& t = ctx.tmpl;
        for (std::size_t d = 0; d < ctx.varied.size(); ++d) {
            const ParameterDomain& p = t.parameters[ctx.varied[d]];
            if (p.kind != ParameterKind::ego_speed || !set(r, 0) || !set(r, d + 1)) {
                continue;
            }
            const Anchor& a = ctx.anchors[r[0]];
            const double kmh = p.limit_fractions.empty() ? *parse_number(p.values[r[d + 1]])
                                                         : p.limit_fractions[r[d + 1]] * a.speed_limit_kmh;
            if (t.speed_within_limit && std::isfinite(a.speed_limit_kmh) && kmh > a.speed_limit_kmh + 1e-9) {
                return false;
            }
            // A train cannot run faster than it can: checked once its asset is chosen.
            bool ego_chosen = true;
            for (std::size_t e = 0; e < ctx.varied.size(); ++e) {
                const ParameterDomain& q = t.parameters[ctx.varied[e]];
                ego_chosen = ego_chosen && !(q.kind == ParameterKind::actor_asset && q.actor == "Ego" && !set(r, e + 1));
            }
            if (const Asset* ego = ego_chosen ? ego_for(ctx, r, kmh) : nullptr;
                ego_chosen && std::isfinite(kmh) && (!ego || kmh > ego->max_speed_mps * 3.6 + 1e-9)) {
                return false;
            }
        }
        for (const auto& x : t.exclusions) {
            bool all = true;
            for (const auto& [name, value] : x.values) {
                std::size_t d = 0;
                while (d < ctx.varied.size() && t.parameters[ctx.varied[d]].name != name) {
                    ++d;
                }
                all = all && d < ctx.varied.size() && set(r, d + 1) &&
                      t.parameters[ctx.varied[d]].values[r[d + 1]] == value;
            }
            if (all) {
                return false;
            }
        }
        return true;
    };
}

// --count caps every strategy's rows per template, as its help says; without
// it, more than max_count_per_template rows (a cover or pairwise array of two
// parameters of a thousand values each has a million) are refused with their
// number, as `full`'s are.
std::vector<Row> capped(std::vector<Row> rows, const GenerateOptions& o, const std::string& where) {
    if (o.count > 0 && rows.size() > o.count) {
        rows.resize(o.count);
    } else if (o.count == 0 && rows.size() > max_count_per_template) {
        throw InputError(where, std::string{"the "} + to_string(o.strategy) + " strategy gives " +
                                    std::to_string(rows.size()) + " rows, more than " +
                                    std::to_string(max_count_per_template) + " (give --count N, or fewer values)");
    }
    return rows;
}

std::vector<Row> rows_for(const std::vector<std::size_t>& sizes, const Validity& valid, const GenerateOptions& o,
                          const std::string& where, TemplateRun& run) {
    std::vector<Row> rows;
    try {
        switch (o.strategy) {
        case Strategy::full: rows = full_factorial(sizes, valid); break;
        case Strategy::pairwise: rows = pairwise(sizes, valid); break;
        case Strategy::random: rows = random_rows(sizes, valid, o.count, o.seed, &run.every_valid_row); break;
        case Strategy::cover: break; // rows come from cover_rows (generate)
        }
    } catch (const std::length_error& e) {
        throw InputError(where, std::string{e.what()} + " (use --strategy pairwise or random, or --max-anchors)");
    }
    return capped(std::move(rows), o, where);
}

std::string scenario_id(const std::string& tmpl, std::size_t n) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "_%04zu", n);
    return tmpl + buf;
}

// Half the longest train the template can run (its Ego asset parameter's
// values, else the default asset of its class: instantiate.cpp's prepare).
double ego_half_length(const Template& t, const Catalog& catalog) {
    double longest = 0.0;
    bool chosen = false;
    for (const auto& p : t.parameters) {
        if (p.kind == ParameterKind::actor_asset && p.actor == "Ego") {
            chosen = true;
            for (const auto& id : p.values) {
                if (const Asset* a = catalog.find(id)) {
                    longest = std::max(longest, a->dimensions.length);
                }
            }
        }
    }
    if (!chosen) {
        const auto assets = catalog.under(t.ego.asset_class);
        longest = assets.empty() ? 0.0 : assets.front()->dimensions.length;
    }
    return longest / 2.0;
}

} // namespace

namespace {

// Numbers every map item (element, attribute, class) an anchor of a template
// exercises, for the set cover of `--strategy cover`: candidates[t][a] lists
// the items of anchor a of template t, none where no row is feasible there.
std::vector<std::vector<std::vector<std::size_t>>> anchor_items(const std::deque<TemplateContext>& ctxs,
                                                                const std::vector<std::vector<char>>& feasible,
                                                                std::size_t& item_count) {
    std::map<std::tuple<std::string, std::string, std::string>, std::size_t> ids;
    std::vector<std::vector<std::vector<std::size_t>>> out;
    for (std::size_t k = 0; k < ctxs.size(); ++k) {
        const TemplateContext& ctx = ctxs[k];
        auto& per_anchor = out.emplace_back();
        for (std::size_t a = 0; a < ctx.anchor_cover.size(); ++a) {
            std::set<std::size_t> items;
            if (!feasible[k][a]) {
                per_anchor.emplace_back(); // no scenario can stand there
                continue;
            }
            for (const auto& v : ctx.anchor_cover[a]) {
                const odd::Element* el = ctx.taxonomy.find(v.element);
                const odd::Attribute* a = el && !v.attribute.empty() ? ctx.taxonomy.attribute(*el, v.attribute) : nullptr;
                if (v.attribute.empty() || (a && countable(*a))) {
                    items.insert(ids.emplace(std::tuple{v.element, v.attribute, v.value_class}, ids.size()).first->second);
                }
            }
            per_anchor.emplace_back(items.begin(), items.end());
        }
    }
    item_count = ids.size();
    return out;
}

// The run's dimensions: the anchor, then each varied parameter.
void parameter_sizes(const Template& t, std::vector<std::size_t>& varied, TemplateRun& run, std::size_t anchors) {
    run.template_id = t.id;
    run.anchors = anchors;
    run.dimensions.push_back("anchor");
    run.sizes.push_back(anchors);
    for (std::size_t i = 0; i < t.parameters.size(); ++i) {
        if (t.parameters[i].kind != ParameterKind::map_value) {
            varied.push_back(i);
            run.dimensions.push_back(t.parameters[i].name);
            run.sizes.push_back(t.parameters[i].values.size());
        }
    }
}

// Per anchor, whether the constraints admit some row there; the others, and
// the parameter values no valid row holds, are recorded in the run (coverage
// says "constraint infeasible").
std::vector<char> feasible_anchors(const TemplateContext& ctx, TemplateRun& run) {
    const Validity valid = validity(ctx);
    std::vector<char> out(ctx.anchors.size(), 0);
    for (std::size_t a = 0; a < ctx.anchors.size(); ++a) {
        Row r(run.sizes.size(), kUnset);
        r[0] = a;
        out[a] = completable(run.sizes, valid, r) ? 1 : 0;
        if (!out[a]) {
            run.infeasible.push_back(ctx.anchors[a].element);
        }
    }
    for (std::size_t d = 1; d < run.sizes.size() && !ctx.anchors.empty(); ++d) {
        for (std::size_t v = 0; v < run.sizes[d]; ++v) {
            Row r(run.sizes.size(), kUnset);
            r[d] = v;
            if (!completable(run.sizes, valid, r)) {
                run.infeasible_values.emplace_back(run.dimensions[d], ctx.tmpl.parameters[ctx.varied[d - 1]].values[v]);
            }
        }
    }
    return out;
}

// Under the cover strategy, the set's size against pairwise over all anchors
// and the full factorial, and the pairs of the parameters alone.
void cover_figures(TemplateRun& run, const Validity& valid, const std::vector<Row>& rows) {
    run.full_factorial = 1.0;
    for (const auto n : run.sizes) {
        run.full_factorial *= static_cast<double>(n);
    }
    run.pairwise_rows = pairwise(run.sizes, valid).size();
    const std::vector<std::size_t> params(run.sizes.begin() + 1, run.sizes.end());
    std::vector<Row> param_rows;
    for (const auto& r : rows) {
        param_rows.emplace_back(r.begin() + 1, r.end());
    }
    if (run.sizes[0] > 0) {
        run.pairs = pair_coverage(params, [&](const Row& r) { return any_anchor(run.sizes[0], valid, r); }, param_rows);
    }
}

} // namespace

Generation generate(const odd::OddProfile& profile, const TemplateSet& templates, const Catalog& catalog,
                    const odd::Taxonomy& taxonomy, const GenerateOptions& options) {
    if (options.strategy == Strategy::random && options.count == 0) {
        throw std::invalid_argument("the random strategy needs a count (--count N)");
    }
    const LineIndex lines(profile);
    Generation out;
    // Anchors and what each exercises, for every template first: the cover
    // strategy chooses anchors across templates.
    std::deque<std::vector<Anchor>> anchors;
    std::deque<TemplateContext> ctxs;
    std::vector<std::vector<char>> feasible; // per template and anchor: some valid row stands there
    for (const Template& t : templates.templates) {
        Anchoring anchoring = find_anchors(profile, lines, t, ego_half_length(t, catalog));
        anchors.push_back(thin(std::move(anchoring.anchors), options.max_anchors));
        ctxs.push_back(TemplateContext{profile, lines, t, catalog, taxonomy, options, anchors.back(), {}, {}, {}, {}});
        TemplateRun& run = out.runs.emplace_back();
        run.skipped = std::move(anchoring.skipped);
        parameter_sizes(t, ctxs.back().varied, run, anchors.back().size());
        prepare(ctxs.back());
        feasible.push_back(feasible_anchors(ctxs.back(), run));
    }
    std::vector<std::vector<std::size_t>> chosen;
    if (options.strategy == Strategy::cover) {
        std::size_t items = 0;
        const auto candidates = anchor_items(ctxs, feasible, items);
        chosen = choose_anchors(candidates, items, options.seed);
    }
    std::set<std::string> used_assets;
    for (std::size_t k = 0; k < ctxs.size(); ++k) {
        const TemplateContext& ctx = ctxs[k];
        const Template& t = ctx.tmpl;
        TemplateRun& run = out.runs[k];
        const Validity valid = validity(ctx);
        const std::string where = templates.source + (t.line > 0 ? ":" + std::to_string(t.line) : "");
        std::vector<Row> rows;
        if (options.strategy == Strategy::cover) {
            // Every template with anchors takes part: its parameters' pairs
            // need a row even where the set cover chose none of its anchors.
            const auto first = std::find(feasible[k].begin(), feasible[k].end(), 1);
            if (chosen[k].empty() && first != feasible[k].end()) {
                chosen[k].push_back(static_cast<std::size_t>(first - feasible[k].begin()));
            }
            rows = capped(cover_rows(run.sizes, valid, chosen[k]), options, where + ": template '" + t.id + "'");
            cover_figures(run, valid, rows);
        } else {
            rows = rows_for(run.sizes, valid, options, where + ": template '" + t.id + "'", run);
            run.pairs = pair_coverage(run.sizes, valid, rows);
        }
        run.rows = rows.size();
        for (std::size_t n = 0; n < rows.size(); ++n) {
            out.scenarios.push_back(instantiate(ctx, rows[n], scenario_id(t.id, n + 1)));
            for (const auto& [actor, id] : out.scenarios.back().assets) {
                used_assets.insert(id);
            }
        }
    }
    for (const auto& a : catalog.assets) {
        if (used_assets.contains(a.id)) {
            out.catalog_entries.push_back(actor_from(a, a.id, entry_name(a, options.target)));
        }
    }
    return out;
}

} // namespace railodd::scenario

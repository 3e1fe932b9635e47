// Chains run so that every link a train passes runs end -> start (what CARLA,
// which follows lane ids and never contactPoint, needs to walk a network),
// and an alignment reversed is the same curve run the other way.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/vertex_legs.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/sample/sample_route.hpp"
#include "test_support.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <regex>

using namespace railodd;
using namespace railodd::geometry;

namespace {

// The sample route with the node order of every other way reversed: the same
// network as mappers might draw it, ways in no particular direction.
test::fs::path sample_with_ways_reversed(const test::fs::path& dir) {
    const sample::SampleFiles files = sample::write_sample_route(dir / "sample");
    const std::string text = test::read_file(files.osm);
    const std::regex way(R"((<way [^>]*>)((?:\s*<nd ref="\d+"/>)+))");
    std::string out;
    std::size_t n = 0;
    auto last = text.cbegin();
    for (std::sregex_iterator it(text.begin(), text.end(), way), end; it != end; ++it) {
        const std::smatch& m = *it;
        out.append(last, m[0].first);
        std::string nds = m[2].str();
        if (n++ % 2 == 1) {
            std::vector<std::string> refs;
            const std::regex nd(R"(<nd ref="\d+"/>)");
            for (std::sregex_iterator r(nds.begin(), nds.end(), nd), e; r != e; ++r) {
                refs.push_back(r->str());
            }
            nds.clear();
            for (auto r = refs.rbegin(); r != refs.rend(); ++r) {
                nds += "\n    " + *r;
            }
        }
        out += m[1].str() + nds;
        last = m[0].second;
    }
    out.append(last, text.cend());
    EXPECT_GT(n, 4u);
    return test::write_file(dir / "reversed.osm", out);
}

// Movements (G2 pairs of ends at a vertex) whose two ends both start or both
// end there.
std::size_t reversing_movements(const TrackGraph& g, const FittedNetwork& net, std::size_t& movements) {
    std::size_t bad = 0;
    for (const auto& legs : legs_by_vertex(g, net)) {
        for (std::size_t i = 0; i < legs.size(); ++i) {
            for (std::size_t j = i + 1; j < legs.size(); ++j) {
                if (g2_mismatch(legs[i], legs[j]).empty()) {
                    ++movements;
                    bad += legs[i].at_start == legs[j].at_start ? 1 : 0;
                }
            }
        }
    }
    return bad;
}

} // namespace

TEST(ChainOrientation, ReversedAlignmentIsTheSameCurveRunBackwards) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int round = 0; round < 50; ++round) {
        Alignment a;
        a.start = {u(rng) * 100.0, u(rng) * 100.0, (u(rng) - 0.5) * 6.0, 0.0};
        double k = 0.0;
        for (int i = 0; i < 6; ++i) {
            const double next = (u(rng) - 0.5) / 300.0;
            a.primitives.push_back(i % 2 ? make_arc(50.0 + 200.0 * u(rng), k) : make_spiral(20.0 + 80.0 * u(rng), k, next));
            k = i % 2 ? k : next;
        }
        const Alignment r = reversed(a);
        const double len = length(a);
        ASSERT_NEAR(length(r), len, 1e-9);
        for (double s = 0.0; s <= len; s += len / 37.0) {
            const Pose p = evaluate(a, len - s), q = evaluate(r, s);
            EXPECT_NEAR(p.x, q.x, 1e-7) << round << " s " << s;
            EXPECT_NEAR(p.y, q.y, 1e-7) << round << " s " << s;
            EXPECT_NEAR(std::remainder(q.hdg - p.hdg - std::numbers::pi, 2 * std::numbers::pi), 0.0, 1e-9);
        }
        // Inside a primitive (not at a joint, where evaluate reports the later one).
        EXPECT_NEAR(evaluate(r, 1.0).curvature, -evaluate(a, len - 1.0).curvature, 1e-12);
    }
}

TEST(ChainOrientation, EveryLinkRunsEndToStartWhateverWayTheWaysWereDrawn) {
    const auto dir = test::scratch_dir();
    for (const bool reverse : {false, true}) {
        const test::fs::path osm = reverse ? sample_with_ways_reversed(dir)
                                           : sample::write_sample_route(dir / "plain").osm;
        const ingest::IngestResult in = ingest::read_osm(osm, {});
        const TrackGraph g = build_track_graph(in.tracks, in.features);
        const FittedNetwork net = fit_track_graph(g, FitOptions{});
        std::size_t movements = 0;
        EXPECT_EQ(reversing_movements(g, net, movements), 0u) << (reverse ? "ways reversed" : "as drawn");
        EXPECT_GE(movements, 6u) << "three switches, two movements each";
        EXPECT_EQ(net.reversing_links, 0u);
        for (const Chain& c : net.chains) {
            for (const ChainItem& item : c.items) {
                EXPECT_EQ(item.reversed, net.edges[item.edge].reversed);
            }
        }
    }
}

// Which left-out nodes of a chain's design are strays, and how far the
// design lies from the rest (design_pass.hpp).
#include "design_pass.hpp"

#include <algorithm>
#include <cstddef>

namespace railodd::geometry::fit {

namespace {

// The weights with every left-out node the final alignment passes within
// four sigma taken as followed: a good node left out by one pass and
// passed by the next within its noise is no part of a stray run. Counted
// in a run, it made two strays beside it a stretch the design missed, and
// the chain was patched by corners through them (dense tied truth seed
// 1086 at 0.1 m: a good node 0.14 m off left out after two strays 4.9 and
// 9.4 m off, the route 8.0 m off). Four sigma, as the extracts' test of
// the nodes left far off reads them.
constexpr double followed_within = 4.0;

// Only the left-out nodes are projected: mostly there are none, and the
// fit has measured the rest already.
std::vector<double> left_out_after(const Alignment& a, const std::vector<Point>& all, std::vector<double> weight,
                                   double sigma) {
    std::vector<std::size_t> out;
    std::vector<Point> at;
    for (std::size_t i = 0; i < weight.size() && i < all.size(); ++i) {
        if (weight[i] == 0.0) {
            out.push_back(i);
            at.push_back(all[i]);
        }
    }
    const std::vector<double> d = distances(a, at);
    for (std::size_t k = 0; k < out.size(); ++k) {
        if (d[k] <= followed_within * sigma) {
            weight[out[k]] = 1.0;
        }
    }
    return weight;
}

} // namespace

std::vector<char> strays(const std::vector<double>& weight, bool tied_start, bool tied_end) {
    constexpr std::size_t stray_run = 2, witnesses = 2;
    std::vector<std::size_t> kept_before(weight.size() + 1, 0);
    for (std::size_t i = 0; i < weight.size(); ++i) {
        kept_before[i + 1] = kept_before[i] + (weight[i] > 0.0 ? 1 : 0);
    }
    std::vector<char> out(weight.size(), 0);
    for (std::size_t i = 0; i < weight.size();) {
        std::size_t j = i;
        while (j < weight.size() && weight[j] == 0.0) {
            ++j;
        }
        if (j == i) {
            ++i;
            continue;
        }
        const std::size_t before = kept_before[i] + (tied_start ? 1 : 0);
        const std::size_t after = kept_before.back() - kept_before[j] + (tied_end ? 1 : 0);
        if (j - i <= stray_run && before >= witnesses && after >= witnesses) {
            std::fill(out.begin() + static_cast<std::ptrdiff_t>(i), out.begin() + static_cast<std::ptrdiff_t>(j), 1);
        }
        i = j;
    }
    return out;
}

double followed_max(const Alignment& a, const std::vector<Point>& all, const std::vector<char>& stray) {
    std::vector<Point> judged;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (!stray[i]) {
            judged.push_back(all[i]);
        }
    }
    return measure_fit(a, judged).max_m;
}

std::vector<char> fitted_strays(const Alignment& a, const std::vector<Point>& all, const std::vector<double>& weight,
                                double sigma, bool tied_start, bool tied_end) {
    return strays(left_out_after(a, all, weight, sigma), tied_start, tied_end);
}

} // namespace railodd::geometry::fit

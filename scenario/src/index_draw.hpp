#pragma once
// Seeded index draws shared by the random and cover strategies. Internal to
// the scenario library.
#include <cstddef>
#include <cstdint>
#include <random>

namespace railodd::scenario {

// Index draws by rejection, not std::uniform_int_distribution, whose
// algorithm differs between standard libraries: the same on every platform.
class IndexDraw {
public:
    explicit IndexDraw(std::uint64_t seed) : rng_(seed) {}
    std::size_t operator()(std::size_t n) {
        const std::uint64_t bound = UINT64_MAX - UINT64_MAX % n;
        std::uint64_t x = 0;
        do {
            x = rng_();
        } while (x >= bound);
        return static_cast<std::size_t>(x % n);
    }

private:
    std::mt19937_64 rng_;
};

} // namespace railodd::scenario

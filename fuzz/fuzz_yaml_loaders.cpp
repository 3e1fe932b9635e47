// The YAML loaders: taxonomy, ODD spec, asset catalog, templates. The first
// byte picks the loader (the others read the shipped files they depend on).
#include "fuzz_support.hpp"

#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/templates.hpp"

namespace {

const std::filesystem::path data{RAILODD_DATA_DIR};

const railodd::odd::Taxonomy& taxonomy() {
    static const auto t = railodd::odd::load_taxonomy(data / "odd" / "railway_odd.yaml");
    return t;
}

const railodd::scenario::Catalog& catalog() {
    static const auto c = railodd::scenario::load_catalog(data / "scenario" / "assets.yaml", taxonomy());
    return c;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data_, std::size_t size) {
    if (size < 1) {
        return 0;
    }
    const auto file = railodd::fuzz::as_file("in.yaml", data_ + 1, size - 1);
    railodd::fuzz::expect_clean([&] {
        switch (data_[0] % 4) {
        case 0: (void)railodd::odd::load_taxonomy(file); break;
        case 1: (void)railodd::odd::load_odd_spec(file, taxonomy()); break;
        case 2: (void)railodd::scenario::load_catalog(file, taxonomy()); break;
        default: (void)railodd::scenario::load_templates(file, taxonomy(), catalog()); break;
        }
    });
    return 0;
}

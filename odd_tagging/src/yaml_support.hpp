#pragma once
// The loaders here use the shared yaml-cpp helpers under their old name.
#include "railodd/util/yaml_support.hpp"

namespace railodd::odd {
namespace yaml = railodd::yaml;
} // namespace railodd::odd
